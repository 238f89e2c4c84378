// What the page controls: parameters, rng seed, region, seeds. Together with the options given
// on the command line they make the generated program's arguments.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace acanthus {

struct PreviewSettings {
    std::map<std::string, std::string> params;  // --param NAME=VALUE
    std::string rng_seed;                       // empty: the program's default
    std::string region;                         // path or rect:W,H...; empty: the built-in panel
    std::vector<std::string> seeds;             // "X,Y"
    std::vector<std::string> other;             // every other program option, passed as given
    double time_limit = 20;                     // --time-limit of every preview run
    bool time_limit_given = false;              // on the command line (else the preview's)

    // The program's arguments (without -o and the preview's own outputs). For the command
    // shown to the user, the preview's own default --time-limit is left out: the same picture
    // comes from a run without it.
    std::vector<std::string> arguments(bool shown = false) const;

    // Splits program options from the command line into the fields above; false with `error`
    // set on an option the preview sets itself (-o, --metrics, --frames, ...).
    bool take(const std::vector<std::string>& args, std::string& error);
};

}  // namespace acanthus
