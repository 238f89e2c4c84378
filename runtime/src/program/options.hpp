// The generated program's command line (docs/cli.md), parsed with CLI11.
#pragma once

#include <acanthus/growth.hpp>
#include <acanthus/pattern.hpp>
#include <acanthus/render.hpp>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace acanthus::detail {

enum class ProgressMode { automatic, forced, quiet };

struct ProgramOptions {
    std::string region;               // --region argument; empty: Region::default_panel()
    std::string band;                 // --band centre line (SVG); empty: none
    double band_width = 0;            // --band-width
    std::vector<std::string> params;  // --param NAME=VALUE, in command-line order
    bool list_params = false;
    GrowthOptions growth;  // seeds, rng seed, resolution, epsilon, limits, engine
    std::string output;    // -o; "-" is SVG on stdout
    RenderOptions render;
    std::string json;  // --json; empty: none
    bool metrics = false;
    ProgressMode progress = ProgressMode::automatic;
    double body_time_limit = 10;  // --body-time-limit: seconds one body may run (0: no limit)
    long debug_iteration = 0;     // --debug-frame N (0: none)
    std::string debug_path;
    std::string frames_dir;  // --frames; empty: none
    long frames_every = 1;
    std::string partial;         // --partial: the growth so far as SVG or PNG; empty: none
    double partial_every = 0.1;  // --partial-every: seconds between two pictures
    std::string view;            // --view: the picture as PNG for a viewer too; empty: none
    int view_width = 0, view_height = 0;  // --view-size: what --view and a PNG --partial fit
};

// Parses argv. Prints --help / --version to stdout and returns nullopt (exit 0). Every malformed
// command line throws UsageError with CLI11's or our message (exit 2). Nothing is validated
// against the region or the pattern's parameters here; run_program does that before growing.
std::optional<ProgramOptions> parse_program_options(const Pattern& pattern,
                                                    const std::string& program, int argc,
                                                    char** argv);

// A decimal unsigned 64-bit integer, digits only; nullopt otherwise (no sign, no exponent, no
// clamping).
std::optional<std::uint64_t> parse_rng_seed(const std::string& text);

// --view-size "WxH", each 16 to 8192 pixels; UsageError otherwise.
std::pair<int, int> parse_view_size(const std::string& text);

// "X,Y" with two finite numbers; nullopt otherwise.
std::optional<Point> parse_seed(const std::string& text);

}  // namespace acanthus::detail
