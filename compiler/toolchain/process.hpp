// Runs a child process (the C++ compiler) with inherited stdio and waits for it.
#pragma once

#include <string>
#include <vector>

namespace acanthus {

// Exit status of the process, or -1 with `error` set when it could not be started or was
// killed by a signal.
int run_process(const std::vector<std::string>& argv, std::string& error);

// As run_process, with the process's standard output and error (at most 1 MiB) in `output`.
int run_process_output(const std::vector<std::string>& argv, std::string& output,
                       std::string& error);

// Shell-style quoting, for showing a command line.
std::string quote_command(const std::vector<std::string>& argv);

}  // namespace acanthus
