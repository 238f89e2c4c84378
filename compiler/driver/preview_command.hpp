// `acanthus preview FILE.acr [program options] [--port N] [--host ADDR] [--memory-limit SIZE]
// [--editor CMD]`: the command line of the preview server (preview/server/serve.hpp).
#pragma once

#include <string>
#include <vector>

#include "toolchain/program_build.hpp"
#include "toolchain/toolchain.hpp"

namespace acanthus {

// `args` are everything after FILE (program options mixed with the server's options).
int run_preview(const std::string& input, const std::vector<std::string>& includes,
                const Toolchain& toolchain, const BuildOptions& build,
                const std::vector<std::string>& args);

}  // namespace acanthus
