// `acanthus preview FILE.acr [program options] [--port N] [--host ADDR]`: a live page for the
// rule file, served until Ctrl-C.
#pragma once

#include <string>
#include <vector>

#include "driver/build_command.hpp"
#include "driver/toolchain.hpp"

namespace acanthus {

// `args` are everything after FILE (program options mixed with --port and --host).
int run_preview(const std::string& input, const std::vector<std::string>& includes,
                const Toolchain& toolchain, const BuildOptions& build,
                const std::vector<std::string>& args);

}  // namespace acanthus
