// The program that runs a preview's rule code: the runtime and stdlib linked once (cached) into
// an executable that loads the rule file's code as a shared library. A save then compiles one
// small library instead of linking a whole program (docs/preview.md, bench/preview.sh).
#pragma once

#include <string>

#include "toolchain/program_build.hpp"
#include "toolchain/toolchain.hpp"

namespace acanthus {

// The host executable for `options` (compiler, optimization, flags), built when missing.
// Run it as `HOST LIBRARY.so [program options]`.
bool preview_host(const Toolchain& toolchain, const BuildOptions& options, std::string& host,
                  std::string& error);

}  // namespace acanthus
