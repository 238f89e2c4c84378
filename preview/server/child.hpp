// A child process of the preview server (the C++ compiler, the generated program): started
// without a shell in a process group of its own, its output captured in files, waited for with
// a deadline and a cancel flag, and killed with everything it started.
#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <vector>

namespace acanthus {

struct ChildRun {
    std::vector<std::string> argv;
    std::string stdout_path;                    // empty: /dev/null
    std::string stderr_path;                    // empty: /dev/null
    double deadline_seconds = 0;                // 0: none
    const std::atomic<bool>* cancel = nullptr;  // set: kill the child and return
    std::function<void()> on_poll;              // called every 10 to 25 ms while it runs
    int wake_fd = -1;    // readable: on_poll at once, not at the next tick (on_poll drains it)
    int cancel_fd = -1;  // readable: `cancel` is looked at once (not drained here)
    unsigned long long memory_limit = 0;  // bytes of address space (RLIMIT_AS); 0: none
};

struct ChildEnd {
    enum class How { exited, signaled, timed_out, cancelled, not_started } how = How::not_started;
    int code = 0;  // exit status, or the signal
    // Processor time (user + system) of the child and the children it waited for, once it ended.
    double cpu_seconds = 0;
    std::string error;  // why it did not start
};

ChildEnd run_child(const ChildRun& run);

// Starts a program that outlives the request (the user's editor): its own process group, no
// output, not waited for (a thread reaps it). False with `error` when it cannot start.
bool spawn_detached(const std::vector<std::string>& argv, std::string& error);

// "exit status 3", "killed by signal 11 (Segmentation fault)", "timed out after 20 s", ...
std::string describe(const ChildEnd& end, double deadline_seconds);

}  // namespace acanthus
