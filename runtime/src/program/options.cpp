// Command-line definition of the generated program. CLI11 does the parsing; the help text is
// written for someone who has never seen the program (groups, defaults, examples).
#include "program/options.hpp"

#include <CLI/CLI.hpp>
#include <acanthus/canvas.hpp>
#include <acanthus/distance_metric.hpp>
#include <acanthus/error.hpp>
#include <acanthus/int_pair.hpp>
#include <acanthus/param.hpp>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <iostream>
#include <sstream>
#include <tuple>
#include <utility>
#include <vector>

#include "output/repeat.hpp"
#include "symmetry/frieze_group.hpp"
#include "symmetry/wallpaper_group.hpp"

#ifndef ACANTHUS_VERSION
#define ACANTHUS_VERSION "unknown"
#endif

namespace acanthus::detail {

namespace {

std::optional<double> parse_number(std::string_view text) {
    // Trim surrounding blanks so "--seed '10, 20'" works as typed.
    while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
    while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    double v = 0;
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || ec != std::errc() || ptr != text.data() + text.size() || !std::isfinite(v))
        return std::nullopt;
    return v;
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

// Validators return an empty string when the value is good, else the message.
auto positive(const char* what) {
    return [what](const std::string& s) -> std::string {
        auto v = parse_number(s);
        if (!v || *v <= 0)
            return std::string(what) + " must be a number greater than 0, not '" + s + "'";
        return {};
    };
}

auto at_least(const char* what, double low, double high) {
    return [=](const std::string& s) -> std::string {
        auto v = parse_number(s);
        if (!v || *v < low || *v > high) {
            std::ostringstream m;
            m << what << " must be between " << low << " and " << high << ", not '" << s << "'";
            return m.str();
        }
        return {};
    };
}

std::string check_seed(const std::string& s) {
    if (!parse_seed(s))
        return "--seed expects X,Y (two numbers, e.g. --seed 120,80), not '" + s + "'";
    return {};
}

std::string check_rng_seed(const std::string& s) {
    if (!parse_rng_seed(s))
        return "expects an integer from 0 to 18446744073709551615, not '" + s + "'";
    return {};
}

std::string check_param(const std::string& s) {
    auto eq = s.find('=');
    if (eq == std::string::npos || eq == 0)
        return "--param expects NAME=VALUE (e.g. --param max_radius=2.5), not '" + s + "'";
    return {};
}

std::string check_color(const std::string& s) {
    try {
        parse_color(s);
    } catch (const InputError& e) {
        return std::string("--background: ") + e.what();
    }
    return {};
}

std::string check_style(const std::string& s) {
    for (const char* known : {"drawn", "outline", "filled", "order", "overlay"})
        if (s == known) return {};
    return "--style must be drawn, outline, filled, order or overlay, not '" + s + "'";
}

std::string check_distance(const std::string& s) {
    if (distance_metric_named(s)) return {};
    return "--distance must be euclidean or manhattan, not '" + s + "'";
}

std::string check_symmetry(const std::string& s) {
    try {
        Symmetry::parse(s);
    } catch (const UsageError& e) {
        return e.what();
    }
    return {};
}

std::string check_symmetry_center(const std::string& s) {
    if (!parse_seed(s))
        return "--symmetry-center expects X,Y (two numbers, e.g. --symmetry-center 150,150), "
               "not '" +
               s + "'";
    return {};
}

std::string footer(const Pattern& pattern, const std::string& program) {
    std::ostringstream f;
    if (!pattern.params.empty()) {
        f << "Parameters of this pattern (set with --param NAME=VALUE, see --list-params):\n";
        for (const ParamInfo& p : pattern.params)
            f << "  " << p.name << " (" << p.type << ", default " << p.default_text << ")\n";
        f << "\n";
    }
    std::vector<std::pair<std::string, std::string>> examples{
        {"", "grow into the built-in panel, write " + program + ".svg"},
        {"--region panel.svg -o panel.png --width 1200", "an SVG panel, as a PNG"},
        {"--region rect:400,200 --seed 100,100 --seed 300,100", "two seeds"},
        {"--region circle:150 --rng-seed 7 -o disc.pdf", "another random variation"},
        {"--style order -o order.svg", "colour by placement order"}};
    if (!pattern.params.empty()) {
        const ParamInfo& p = pattern.params.front();
        examples.push_back({"--param " + p.name + "=" + p.default_text + " --list-params",
                            "set and show parameters"});
    }
    examples.push_back({"--metrics -o out.svg > metrics.json", "run metrics as JSON"});
    examples.push_back({"-o - | rsvg-convert -o out.png", "SVG on stdout"});
    examples.push_back({"--debug-frame 40 iteration40.png", "what iteration 40 saw"});
    examples.push_back({"--frames frames --every 25", "frames for an animation"});
    std::size_t column = 0;
    for (const auto& example : examples)
        column = std::max(column, program.size() + example.first.size() + 5);
    f << "Examples:\n";
    for (const auto& [args, what] : examples) {
        std::string line = "  " + program + (args.empty() ? "" : " " + args);
        f << line << std::string(column - line.size(), ' ') << what << "\n";
    }
    f << "\n"
      << "Output format follows the -o extension: .svg .pdf .ps .eps .png. Files are written\n"
      << "completely or not at all; a failed run leaves an existing file untouched.\n"
      << "Exit status: 0 done, 1 bad input (region, parameter, seed, file), 2 bad usage,\n"
      << "3 a rule failed at run time (the message names the rule and its line).";
    return f.str();
}

}  // namespace

std::optional<std::uint64_t> parse_rng_seed(const std::string& text) {
    if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
        return std::nullopt;
    std::uint64_t v = 0;
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || ptr != text.data() + text.size()) return std::nullopt;
    return v;
}

std::optional<Point> parse_seed(const std::string& text) {
    auto comma = text.find(',');
    if (comma == std::string::npos) return std::nullopt;
    auto x = parse_number(std::string_view(text).substr(0, comma));
    auto y = parse_number(std::string_view(text).substr(comma + 1));
    if (!x || !y) return std::nullopt;
    return Point{*x, *y};
}

std::pair<int, int> parse_view_size(const std::string& text) {
    const auto size = read_view_size(text);
    if (!size)
        throw UsageError("--view-size expects WxH, pixels from " + std::to_string(view_size_min) +
                         " to " + std::to_string(view_size_max) + " (e.g. 1200x800), not '" + text +
                         "'");
    return *size;
}

std::optional<ProgramOptions> parse_program_options(const Pattern& pattern,
                                                    const std::string& program, int argc,
                                                    char** argv) {
    ProgramOptions o;
    o.output = (pattern.name.empty() ? std::string("acanthus") : pattern.name) + ".svg";

    std::string description = program + ": grows the '" + pattern.name + "' ornament";
    if (!pattern.file.empty()) description += " (rule file " + pattern.file + ")";
    description += " into a region and renders it.";
    CLI::App app{description, program};
    app.get_formatter()->column_width(34);
    app.footer(footer(pattern, program));
    app.set_help_flag("-h,--help", "Print this help and exit");
    app.set_version_flag("--version", program + " (Acanthus " ACANTHUS_VERSION ")",
                         "Print the version and exit");

    std::vector<std::string> seeds;
    std::string rng_seed;
    std::string background;
    std::pair<long, std::string> debug_frame{0, ""};

    const char* region_group = "Region and seeds";
    app.add_option("--region", o.region,
                   "SVG file, or rect:W,H circle:R ellipse:RX,RY (default: built-in panel)")
        ->type_name("FILE.svg|SHAPE")
        ->group(region_group);
    auto* band_option =
        app.add_option("--band", o.band,
                       "Grow in a band along the centre line of this SVG path, drawn bent onto it")
            ->type_name("PATH.svg")
            ->excludes("--region")
            ->group(region_group);
    app.add_option("--band-width", o.band_width, "The band's width (with --band)")
        ->type_name("W")
        ->needs(band_option)
        ->group(region_group);
    band_option->needs("--band-width");
    app.add_option("--seed", seeds,
                   "Seed position (repeatable; default: centre of the largest inscribed circle)")
        ->type_name("X,Y")
        ->allow_extra_args(false)
        ->check(check_seed)
        ->group(region_group);
    app.add_option("--rng-seed", rng_seed,
                   "Random seed for rule bodies (same seed, same ornament; default 1)")
        ->type_name("N")
        ->check(check_rng_seed)
        ->group(region_group);

    const char* param_group = "Pattern parameters";
    app.add_option("--param", o.params, "Set a %param of the rule file (repeatable)")
        ->type_name("NAME=VALUE")
        ->allow_extra_args(false)
        ->check(check_param)
        ->group(param_group);
    app.add_flag("--list-params", o.list_params,
                 "List parameters: name, type, default, current value; then exit")
        ->group(param_group);
    // Libraries' own options (acanthus/param.hpp): each one a %param of this pattern, set
    // after every --param.
    std::vector<std::pair<std::string, std::string>> flag_values;  // param, value; in order
    for (const ParamFlag& f : param_flags()) {
        const bool known = std::any_of(pattern.params.begin(), pattern.params.end(),
                                       [&](const ParamInfo& p) { return p.name == f.param; });
        if (!known) continue;
        app.add_option_function<std::string>(
               f.flag,
               [&flag_values, param = f.param](const std::string& v) {
                   flag_values.emplace_back(param, v);
               },
               f.help + " (--param " + f.param + "=VALUE)")
            ->type_name(f.type_name)
            ->allow_extra_args(false)
            ->group(param_group);
    }

    const char* growth_group = "Growth";
    app.add_option("--resolution", o.growth.resolution,
                   "Growth buffer pixels on the region's longer side")
        ->type_name("PX")
        ->capture_default_str()
        ->check(at_least("--resolution", 16, 16384))
        ->group(growth_group);
    app.add_option("--epsilon", o.growth.epsilon,
                   "Parent search distance around the empty circle (default: 2 pixels)")
        ->type_name("E")
        ->check(positive("--epsilon"))
        ->group(growth_group);
    app.add_option("--min-radius", o.growth.min_radius,
                   "Smallest empty circle considered (default: 1 pixel)")
        ->type_name("R")
        ->check(positive("--min-radius"))
        ->group(growth_group);
    app.add_option("--max-elements", o.growth.max_elements, "Stop after N elements")
        ->type_name("N")
        ->capture_default_str()
        ->check(at_least("--max-elements", 1, 1e15))
        ->group(growth_group);
    app.add_option("--max-iterations", o.growth.max_iterations, "Stop after N iterations")
        ->type_name("N")
        ->capture_default_str()
        ->check(at_least("--max-iterations", 1, 1e15))
        ->group(growth_group);
    app.add_option("--time-limit", o.growth.time_limit,
                   "Stop growing after S seconds (result then depends on machine speed)")
        ->type_name("S")
        ->check(positive("--time-limit"))
        ->group(growth_group);
    app.add_option("--body-time-limit", o.body_time_limit,
                   "Stop with an error (exit 3) when one rule body runs this long without "
                   "reporting progress (0: no limit)")
        ->type_name("S")
        ->capture_default_str()
        ->check(at_least("--body-time-limit", 0, 1e9))
        ->group(growth_group);
    app.add_flag("--reference-engine", o.growth.reference_engine,
                 "Recompute the whole distance field each iteration (slow, same result)")
        ->group(growth_group);
    app.add_option_function<std::string>(
           "--distance",
           [&o](const std::string& s) { o.growth.distance = *distance_metric_named(s); },
           "Metric of the distance field: euclidean (exact, the default) or manhattan (the "
           "paper's MAT; a different ornament)")
        ->type_name("METRIC")
        ->check(check_distance)
        ->group(growth_group);

    const char* symmetry_group = "Symmetry";
    std::string symmetry, symmetry_center;
    auto* symmetry_option =
        app.add_option("--symmetry", symmetry,
                       "Grow a rosette: cN (N rotations) or dN (N rotations and N mirrors), "
                       "e.g. d8; no element overlaps an image of another or of itself")
            ->type_name("cN|dN")
            ->check(check_symmetry)
            ->group(symmetry_group);
    app.add_option("--symmetry-center", symmetry_center,
                   "Centre of the rosette (default: centre of the region's largest inscribed "
                   "circle)")
        ->type_name("X,Y")
        ->check(check_symmetry_center)
        ->needs(symmetry_option)
        ->group(symmetry_group);
    std::string frieze, wallpaper, tile;
    double period = 0;
    auto* frieze_option =
        app.add_option("--frieze", frieze,
                       "Grow a frieze along x about the region's horizontal centre line: p1 p11g "
                       "p1m1 p11m p2 p2mg p2mm (needs --period)")
            ->type_name("G")
            ->excludes(symmetry_option)
            ->group(symmetry_group);
    auto* period_option =
        app.add_option("--period", period, "The frieze's period along x, in user units")
            ->type_name("P")
            ->needs(frieze_option)
            ->group(symmetry_group);
    frieze_option->needs(period_option);
    auto* wallpaper_option =
        app.add_option("--wallpaper", wallpaper,
                       "Grow a seamless tile under a wallpaper group, p1 ... p6m (needs --tile; "
                       "the region is the tile)")
            ->type_name("G")
            ->excludes(symmetry_option)
            ->excludes(frieze_option)
            ->group(symmetry_group);
    auto* tile_option =
        app.add_option("--tile", tile,
                       "The wallpaper's tile: sides (W, 0) and H at ANGLE degrees (default 90)")
            ->type_name("W,H[,ANGLE]")
            ->needs(wallpaper_option)
            ->group(symmetry_group);
    wallpaper_option->needs(tile_option);

    const char* output_group = "Output";
    app.add_option("-o,--output", o.output,
                   "Format from the extension; '-' is SVG on stdout (default: " + o.output + ")")
        ->type_name("OUT.svg|.pdf|.ps|.eps|.png")
        ->group(output_group);
    app.add_option("--width", o.render.width,
                   "Output width: pixels (PNG) or points (SVG, PDF, PS, EPS)")
        ->type_name("PX")
        ->capture_default_str()
        ->check(at_least("--width", 1, 32767))
        ->group(output_group);
    app.add_option("--style", o.render.style,
                   "drawn (%draw, the default), outline or filled (the proxies), order "
                   "(colour by placement order), overlay (%draw over faint proxies)")
        ->type_name("STYLE")
        ->capture_default_str()
        ->check(check_style)
        ->group(output_group);
    app.add_option("--background", background,
                   "#rgb, #rrggbb, #rrggbbaa or a CSS colour name (default: none)")
        ->type_name("COLOR")
        ->check(check_color)
        ->group(output_group);
    bool no_outline = false;
    app.add_flag("--no-region-outline", no_outline, "Do not draw the region's outline")
        ->group(output_group);
    app.add_option("--stroke", o.render.stroke, "Skeletal stroke drawn along curve proxies")
        ->type_name("NAME")
        ->group(output_group);
    app.add_option_function<std::string>(
           "--repeat",
           [&o](const std::string& s) {
               std::tie(o.render.repeat_x, o.render.repeat_y) = parse_repeat(s);
           },
           "Draw the tile (the wallpaper tile, else the region's bounding box) N x M times, for "
           "a look at the repeat")
        ->type_name("NxM")
        ->group(output_group);
    app.add_flag("--svg-pattern", o.render.svg_pattern,
                 "Write the SVG as a <pattern> of the tile and a shape filled with it")
        ->group(output_group);
    app.add_option("--json", o.json, "Also write the element tree as JSON")
        ->type_name("TREE.json")
        ->group(output_group);
    app.add_flag("--metrics", o.metrics, "Print one JSON object of run metrics on stdout")
        ->group(output_group);

    const char* watch_group = "Watching the growth";
    bool progress = false, quiet = false;
    auto* progress_flag =
        app.add_flag("--progress", progress, "Progress on stderr even when it is not a terminal")
            ->group(watch_group);
    app.add_flag("--quiet", quiet, "No progress line (by default shown on a terminal after 1 s)")
        ->excludes(progress_flag)
        ->group(watch_group);
    app.add_option("--debug-frame", debug_frame,
                   "Picture of iteration N: buffer, candidates, C, parents (PNG)")
        ->option_text("N DEBUG.png")
        ->group(watch_group);
    auto* frames = app.add_option("--frames", o.frames_dir,
                                  "PNG frames of the growth: DIR/frame-000001.png, ...")
                       ->type_name("DIR")
                       ->group(watch_group);
    app.add_option("--every", o.frames_every, "With --frames: a frame every K iterations")
        ->type_name("K")
        ->capture_default_str()
        ->check(at_least("--every", 1, 1e15))
        ->needs(frames)
        ->group(watch_group);
    auto* partial =
        app.add_option("--partial", o.partial,
                       "The growth so far as SVG or PNG, replaced while it grows (a live view)")
            ->type_name("FILE.svg|.png")
            ->group(watch_group);
    app.add_option("--view", o.view,
                   "The finished picture as PNG too, fitted into --view-size (for a viewer)")
        ->type_name("FILE.png")
        ->group(watch_group);
    app.add_option_function<std::string>(
           "--view-size",
           [&o](const std::string& s) {
               std::tie(o.view_width, o.view_height) = parse_view_size(s);
           },
           "Pixels --view and a PNG --partial fit into (default: --width wide)")
        ->type_name("WxH")
        ->group(watch_group);
    app.add_option("--partial-every", o.partial_every,
                   "With --partial: seconds between two pictures (longer when drawing one is slow)")
        ->type_name("S")
        ->capture_default_str()
        ->check(at_least("--partial-every", 0.01, 3600))
        ->needs(partial)
        ->group(watch_group);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp&) {
        std::cout << app.help() << std::flush;
        return std::nullopt;
    } catch (const CLI::CallForVersion& e) {
        std::cout << e.what() << std::endl;
        return std::nullopt;
    } catch (const CLI::ParseError& e) {
        throw UsageError(e.what());
    }

    for (const auto& [param, value] : flag_values) o.params.push_back(param + "=" + value);
    for (const std::string& s : seeds) o.growth.seeds.push_back(*parse_seed(s));
    if (!symmetry.empty()) {
        o.growth.symmetry = Symmetry::parse(symmetry);
        if (!symmetry_center.empty()) o.growth.symmetry->center = *parse_seed(symmetry_center);
    }
    if (!frieze.empty()) {
        o.growth.frieze = Frieze{frieze, period};
        detail::make_frieze_group(frieze, period);  // UsageError on a bad name or period
    }
    if (!wallpaper.empty()) {
        if (!o.region.empty())
            throw UsageError("--wallpaper grows in its tile (--tile); leave out --region");
        const detail::Tile t = detail::parse_tile(tile);
        o.growth.wallpaper = Wallpaper{wallpaper, t.width, t.height, t.angle};
        o.render.clip_to_region = true;
        o.render.tile = RepeatTile{{0, 0}, t.a(), t.b()};  // --repeat repeats the lattice's cell
        detail::make_wallpaper_group(wallpaper, t);        // UsageError on a lattice it cannot have
    }
    if (!rng_seed.empty()) o.growth.rng_seed = *parse_rng_seed(rng_seed);
    if (!background.empty()) o.render.background = parse_color(background);
    o.render.draw_region = !no_outline;
    if (!o.band.empty() && (o.render.svg_pattern || o.render.repeat_x * o.render.repeat_y > 1))
        throw UsageError("--repeat and --svg-pattern repeat a tile, not a band (--band)");
    if (o.render.svg_pattern && o.output != "-" &&
        (o.output.size() < 4 || lower(o.output.substr(o.output.size() - 4)) != ".svg"))
        throw UsageError("--svg-pattern writes an SVG <pattern>: give -o a .svg file name, not '" +
                         o.output + "'");
    o.progress =
        quiet ? ProgressMode::quiet : (progress ? ProgressMode::forced : ProgressMode::automatic);

    if (debug_frame.first != 0 || !debug_frame.second.empty()) {
        if (debug_frame.first < 1)
            throw UsageError("--debug-frame: the iteration N must be 1 or more, not " +
                             std::to_string(debug_frame.first));
        const std::string& path = debug_frame.second;
        if (path.size() < 5 || lower(path.substr(path.size() - 4)) != ".png")
            throw UsageError("--debug-frame writes a PNG; give a file name ending in .png, not '" +
                             path + "'");
        o.debug_iteration = debug_frame.first;
        o.debug_path = path;
    }
    if (o.output.empty()) throw UsageError("-o needs a file name (or '-' for SVG on stdout)");
    if (o.metrics && o.output == "-")
        throw UsageError(
            "--metrics and -o - both write to stdout; give -o a file name to use --metrics");
    if (o.json == "-") throw UsageError("--json needs a file name");
    return o;
}

}  // namespace acanthus::detail
