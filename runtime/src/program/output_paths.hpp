// The files a run will write must be distinct from each other and from the files it reads:
// `--json out.svg -o out.svg` or `-o panel.svg --region panel.svg` is a usage error (exit 2)
// before anything is grown or written.
#pragma once

#include "program/options.hpp"

namespace acanthus::detail {

// Throws UsageError naming both options when two outputs, or an output and an input, are the
// same file (compared as canonical paths).
void check_output_paths(const ProgramOptions& options);

}  // namespace acanthus::detail
