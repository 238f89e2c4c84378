// Runs a program in a directory with its standard error captured, for the batch's workers
// (toolchain/process.hpp runs the C++ compiler with inherited stdio instead).
#pragma once

#include <string>
#include <vector>

namespace acanthus::batch {

struct ChildResult {
    int exit_status = -1;  // -1: not started or killed by a signal (see `error`)
    std::string error;     // why it could not run, or the signal
    std::string output;    // standard error (and standard output when `merge_stdout`)
};

// Runs argv[0] (a path or a name on PATH) in `directory` (empty: the current one). Standard
// input is /dev/null; standard output is kept only with `merge_stdout`. Safe from several
// threads at once: descriptors are close-on-exec.
ChildResult run_child(const std::vector<std::string>& argv, const std::string& directory,
                      bool merge_stdout = false);

}  // namespace acanthus::batch
