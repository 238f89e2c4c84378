// Each rule file of a batch, compiled once to C++ and built once into the content-hash cache
// `acanthus run` uses (toolchain/program_build.hpp).
#pragma once

#include <string>
#include <vector>

#include "toolchain/program_build.hpp"
#include "toolchain/toolchain.hpp"

namespace acanthus::batch {

struct RuleProgram {
    std::string rule;  // absolute path
    std::string cpp;   // generated C++ (the rule file and every import it read)
    std::vector<std::string> dependencies;  // what `acanthus compile --depfile` lists
    // Changes with the C++, the contents of the rule file and its imports, the compiler command,
    // the runtime and the version.
    std::string key;
    std::string executable;  // set once built
    std::string error;       // the front end's diagnostics or the C++ compiler's messages
};

// Runs the front end over `rule` (no C++ compiler yet): fills cpp and key, or error.
RuleProgram prepare_rule_program(const std::string& rule, const Toolchain& toolchain,
                                 const BuildOptions& options);

// Builds (or finds in the cache) the program; false with `program.error` set, the compiler's
// messages captured rather than printed.
bool build_rule_program(RuleProgram& program, const Toolchain& toolchain,
                        const BuildOptions& options);

}  // namespace acanthus::batch
