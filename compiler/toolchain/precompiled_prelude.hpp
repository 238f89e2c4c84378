// The prelude every generated program includes (<acanthus/rules.hpp> and a few standard
// headers), precompiled once per compiler command line into the cache: parsing it is most of
// the time a small rule file takes to compile, and a preview recompiles on every save.
#pragma once

#include <string>

#include "toolchain/program_build.hpp"
#include "toolchain/toolchain.hpp"

namespace acanthus {

// Sets `options.precompiled_header` to the cached prelude, building it when missing. With
// `options.shared_library` the prelude also declares the vectors the preview host instantiates.
// False with `error` set when it cannot be built (the caller may then build without it). The
// standard and Acanthus headers `generated` includes are precompiled too.
bool use_precompiled_prelude(const Toolchain& toolchain, BuildOptions& options, std::string& error,
                             const std::string& generated = {});

}  // namespace acanthus
