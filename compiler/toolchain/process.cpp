#include "toolchain/process.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>

extern char** environ;

namespace acanthus {

namespace {

// Starts `argv` (with `actions`, if any) and returns its pid, or -1 with `error` set.
pid_t spawn(const std::vector<std::string>& argv, const posix_spawn_file_actions_t* actions,
            std::string& error) {
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    pid_t pid = 0;
    const int rc = posix_spawnp(&pid, args[0], actions, nullptr, args.data(), environ);
    if (rc != 0) {
        error = "cannot run '" + argv[0] + "': " + std::strerror(rc);
        return -1;
    }
    return pid;
}

// Its exit status, or -1 with `error` set.
int wait_for(pid_t pid, const std::vector<std::string>& argv, std::string& error) {
    int status = 0;
    while (waitpid(pid, &status, 0) < 0) {
        if (errno != EINTR) {
            error = std::string("waiting for '") + argv[0] + "': " + std::strerror(errno);
            return -1;
        }
    }
    if (WIFEXITED(status)) return WEXITSTATUS(status);
    error = "'" + argv[0] + "' was killed by signal " + std::to_string(WTERMSIG(status));
    return -1;
}

}  // namespace

int run_process(const std::vector<std::string>& argv, std::string& error) {
    const pid_t pid = spawn(argv, nullptr, error);
    return pid < 0 ? -1 : wait_for(pid, argv, error);
}

int run_process_output(const std::vector<std::string>& argv, std::string& output,
                       std::string& error) {
    int pipe_fds[2];
    if (pipe2(pipe_fds, O_CLOEXEC) != 0) {
        error = std::string("cannot run '") + argv[0] + "': " + std::strerror(errno);
        return -1;
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], 1);
    posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], 2);
    const pid_t pid = spawn(argv, &actions, error);
    posix_spawn_file_actions_destroy(&actions);
    ::close(pipe_fds[1]);
    output.clear();
    char buffer[4096];
    for (ssize_t n; pid >= 0;) {
        n = ::read(pipe_fds[0], buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        if (output.size() < (1u << 20)) output.append(buffer, static_cast<std::size_t>(n));
    }
    ::close(pipe_fds[0]);
    return pid < 0 ? -1 : wait_for(pid, argv, error);
}

std::string quote_command(const std::vector<std::string>& argv) {
    std::string out;
    for (const std::string& a : argv) {
        if (!out.empty()) out += ' ';
        bool plain =
            !a.empty() &&
            a.find_first_not_of(
                "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_./=+,:@") ==
                std::string::npos;
        if (plain) {
            out += a;
        } else {
            out += '\'';
            for (char c : a) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
            out += '\'';
        }
    }
    return out;
}

}  // namespace acanthus
