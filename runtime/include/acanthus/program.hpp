// The generated program's main(): parses the command line, grows, renders.
#pragma once

#include <acanthus/pattern.hpp>

namespace acanthus {

// Returns the process exit code: 0 done, 1 bad input, 2 bad usage, 3 rule failure.
int run_program(const Pattern& pattern, int argc, char** argv);

}  // namespace acanthus
