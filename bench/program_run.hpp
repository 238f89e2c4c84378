// Shared by the stdlib benchmarks: build a rule file of rules/ into a program with the build
// tree's `acanthus` and time that program end to end, as a user runs it (a process of its own,
// its `--metrics` JSON read from its stdout). Errors throw std::runtime_error with a message
// naming the command, for main() to print before exiting non-zero.
#pragma once

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace bench {

namespace fs = std::filesystem;

// A fresh directory under the system's temporary directory, removed with all it holds.
class TempDir {
  public:
    TempDir() {
        std::string pattern = (fs::temp_directory_path() / "acanthus-bench-XXXXXX").string();
        if (!mkdtemp(pattern.data()))
            throw std::runtime_error("cannot create a temporary directory: " +
                                     std::string(std::strerror(errno)));
        path_ = pattern;
    }
    ~TempDir() {
        std::error_code ec;  // a destructor must not throw; a leftover directory is harmless
        fs::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const fs::path& path() const { return path_; }

  private:
    fs::path path_;
};

inline std::string command_line(const std::vector<std::string>& argv) {
    std::string s;
    for (const std::string& a : argv) s += (s.empty() ? "" : " ") + a;
    return s;
}

struct Output {
    std::string out;      // everything the process wrote on stdout
    double wall_seconds;  // from spawn to exit: what the user waits for
};

// Runs argv[0] (a path) with argv, stdout captured and stderr passed through, so a failing
// program's own message reaches the bench's stderr. Throws unless it exits with status 0.
inline Output run(const std::vector<std::string>& argv) {
    int fds[2];
    // Close-on-exec on both ends: the child keeps only the dup2'ed copy on its stdout, so EOF
    // arrives when it exits.
    if (pipe2(fds, O_CLOEXEC) != 0)
        throw std::runtime_error("pipe: " + std::string(std::strerror(errno)));
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    const auto t0 = std::chrono::steady_clock::now();
    pid_t pid = 0;
    int spawn_error = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    close(fds[1]);
    if (spawn_error != 0) {
        close(fds[0]);
        throw std::runtime_error("cannot run " + argv[0] + ": " + std::strerror(spawn_error));
    }
    Output result{"", 0};
    char buffer[4096];
    for (;;) {
        ssize_t n = read(fds[0], buffer, sizeof buffer);
        if (n > 0)
            result.out.append(buffer, static_cast<std::size_t>(n));
        else if (n == 0 || errno != EINTR)
            break;
    }
    close(fds[0]);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    result.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (WIFSIGNALED(status))
        throw std::runtime_error(command_line(argv) + ": killed by signal " +
                                 std::to_string(WTERMSIG(status)));
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw std::runtime_error(command_line(argv) + ": exit status " +
                                 std::to_string(WEXITSTATUS(status)));
    return result;
}

// rules/<name>.acr built into <dir>/<name> by the compiler of this build tree, which links the
// build tree's runtime and stdlib (bench/CMakeLists.txt builds them all first).
inline fs::path build_program(const std::string& name, const fs::path& dir) {
    const fs::path program = dir / name;
    const std::string rules = std::string(ACANTHUS_SOURCE_DIR) + "/rules/" + name + ".acr";
    run({ACANTHUS_COMPILER, "build", rules, "-o", program.string()});  // its stdout unused
    if (!fs::exists(program))
        throw std::runtime_error("acanthus build " + rules + " wrote no " + program.string());
    return program;
}

struct ProgramRun {
    long elements = 0;
    double growth_seconds = 0;  // the program's own seconds.growth
    double render_seconds = 0;  // seconds.render
    double wall_seconds = 0;    // the whole process, measured here
};

// One run of a built program with `args`, plus --metrics (its JSON is the last line on stdout)
// and --quiet (no progress line on a terminal).
inline ProgramRun run_program(const fs::path& program, std::vector<std::string> args) {
    args.insert(args.begin(), program.string());
    args.push_back("--metrics");
    args.push_back("--quiet");
    Output o = run(args);
    std::string last = o.out;
    while (!last.empty() && last.back() == '\n') last.pop_back();
    last = last.substr(last.find_last_of('\n') + 1);  // npos + 1 == 0: the one line
    nlohmann::json metrics = nlohmann::json::parse(last, nullptr, false);
    if (metrics.is_discarded() || !metrics.contains("elements") || !metrics.contains("seconds"))
        throw std::runtime_error(command_line(args) + ": no --metrics JSON on stdout: " + o.out);
    ProgramRun r;
    r.elements = metrics["elements"].get<long>();
    r.growth_seconds = metrics["seconds"]["growth"].get<double>();
    r.render_seconds = metrics["seconds"]["render"].get<double>();
    r.wall_seconds = o.wall_seconds;
    return r;
}

inline double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

// Medians over several runs of one program and its arguments. The growth is deterministic, so
// every run must place the same number of elements; a difference is reported, not averaged.
struct ProgramMedian {
    long elements = 0;
    double growth_seconds = 0, render_seconds = 0, wall_seconds = 0;
    std::vector<double> growth, render, wall;

    void add(const ProgramRun& r, const std::string& what) {
        if (!growth.empty() && r.elements != elements)
            throw std::runtime_error(what + ": " + std::to_string(r.elements) +
                                     " elements, an earlier run placed " +
                                     std::to_string(elements));
        elements = r.elements;
        growth.push_back(r.growth_seconds);
        render.push_back(r.render_seconds);
        wall.push_back(r.wall_seconds);
        growth_seconds = median(growth);
        render_seconds = median(render);
        wall_seconds = median(wall);
    }
};

}  // namespace bench
