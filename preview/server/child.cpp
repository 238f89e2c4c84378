#include "server/child.hpp"

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <thread>

extern char** environ;

namespace acanthus {

namespace {

// posix_spawn's attributes and file actions, freed on every path.
class SpawnSetup {
  public:
    SpawnSetup() {
        posix_spawnattr_init(&attr_);
        posix_spawn_file_actions_init(&actions_);
    }
    ~SpawnSetup() {
        posix_spawnattr_destroy(&attr_);
        posix_spawn_file_actions_destroy(&actions_);
    }
    SpawnSetup(const SpawnSetup&) = delete;
    SpawnSetup& operator=(const SpawnSetup&) = delete;

    void prepare(const ChildRun& run) {
        // Own process group: one kill reaches the compiler's own children too. The server
        // blocks SIGINT and SIGTERM in its threads; the child starts with them unblocked.
        sigset_t empty, defaults;
        sigemptyset(&empty);
        sigemptyset(&defaults);
        for (int s : {SIGINT, SIGTERM, SIGPIPE, SIGHUP}) sigaddset(&defaults, s);
        posix_spawnattr_setsigmask(&attr_, &empty);
        posix_spawnattr_setsigdefault(&attr_, &defaults);
        posix_spawnattr_setpgroup(&attr_, 0);
        posix_spawnattr_setflags(
            &attr_, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
        posix_spawn_file_actions_addopen(&actions_, 0, "/dev/null", O_RDONLY, 0);
        open_output(1, run.stdout_path);
        open_output(2, run.stderr_path);
    }
    posix_spawnattr_t* attr() { return &attr_; }
    posix_spawn_file_actions_t* actions() { return &actions_; }

  private:
    void open_output(int fd, const std::string& path) {
        posix_spawn_file_actions_addopen(&actions_, fd, path.empty() ? "/dev/null" : path.c_str(),
                                         O_WRONLY | O_CREAT | O_TRUNC, 0600);
    }
    posix_spawnattr_t attr_;
    posix_spawn_file_actions_t actions_;
};

void kill_group(pid_t pid) {
    ::kill(-pid, SIGKILL);
    ::kill(pid, SIGKILL);
}

}  // namespace

ChildEnd run_child(const ChildRun& run) {
    ChildEnd end;
    if (run.argv.empty()) {
        end.error = "no command";
        return end;
    }
    std::vector<char*> args;
    for (const std::string& a : run.argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    SpawnSetup setup;
    setup.prepare(run);
    pid_t pid = 0;
    int rc = posix_spawnp(&pid, args[0], setup.actions(), setup.attr(), args.data(), environ);
    if (rc != 0) {
        end.error = "cannot run '" + run.argv[0] + "': " + std::strerror(rc);
        return end;
    }
    // posix_spawn returns once the child has run exec: the limit is in place before the
    // program's own code allocates anything worth counting.
    if (run.memory_limit > 0) {
        const rlimit limit{run.memory_limit, run.memory_limit};
        if (prlimit(pid, RLIMIT_AS, &limit, nullptr) != 0) {
            kill_group(pid);
            while (waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
            }
            end.error = std::string("cannot limit the program's memory: ") + std::strerror(errno);
            return end;
        }
    }
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    // Readable when the child ends: the wait between polls ends then, not at the next tick.
    // (The system call itself: glibc 2.36's <sys/pidfd.h> declares it without C linkage.)
    const int exit_fd = static_cast<int>(::syscall(SYS_pidfd_open, pid, 0));
    struct ExitFd {
        int fd;
        ~ExitFd() {
            if (fd >= 0) ::close(fd);
        }
    } exit_fd_closer{exit_fd};
    int status = 0;
    rusage usage{};
    for (;;) {
        pid_t done = wait4(pid, &status, WNOHANG, &usage);
        if (done == pid) break;
        if (done < 0 && errno != EINTR) {
            kill_group(pid);
            end.how = ChildEnd::How::signaled;
            end.code = SIGKILL;
            return end;
        }
        const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
        const bool cancelled = run.cancel && run.cancel->load();
        const bool late = run.deadline_seconds > 0 && elapsed > run.deadline_seconds;
        if (cancelled || late) {
            kill_group(pid);
            while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
            }
            end.how = cancelled ? ChildEnd::How::cancelled : ChildEnd::How::timed_out;
            return end;
        }
        if (run.on_poll) run.on_poll();
        const int tick_ms = elapsed < 2 ? 10 : 25;
        if (exit_fd >= 0 || run.wake_fd >= 0 || run.cancel_fd >= 0) {
            pollfd p[3] = {
                {exit_fd, POLLIN, 0}, {run.wake_fd, POLLIN, 0}, {run.cancel_fd, POLLIN, 0}};
            ::poll(p, 3, tick_ms);  // (a negative fd is left out)
        } else {
            std::this_thread::sleep_for(std::chrono::milliseconds(tick_ms));
        }
    }
    // The group may still hold grandchildren (a compiler's helpers); none must outlive the run.
    ::kill(-pid, SIGKILL);
    const auto seconds = [](const timeval& t) { return t.tv_sec + t.tv_usec * 1e-6; };
    end.cpu_seconds = seconds(usage.ru_utime) + seconds(usage.ru_stime);
    if (WIFEXITED(status)) {
        end.how = ChildEnd::How::exited;
        end.code = WEXITSTATUS(status);
    } else {
        end.how = ChildEnd::How::signaled;
        end.code = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
    }
    return end;
}

bool spawn_detached(const std::vector<std::string>& argv, std::string& error) {
    if (argv.empty()) return error = "no command", false;
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    SpawnSetup setup;
    setup.prepare(ChildRun{});
    pid_t pid = 0;
    const int rc = posix_spawnp(&pid, args[0], setup.actions(), setup.attr(), args.data(), environ);
    if (rc != 0) return error = "cannot run '" + argv[0] + "': " + std::strerror(rc), false;
    std::thread([pid] {
        while (waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
        }
    }).detach();
    return true;
}

std::string describe(const ChildEnd& end, double deadline_seconds) {
    switch (end.how) {
        case ChildEnd::How::exited:
            return "exit status " + std::to_string(end.code);
        case ChildEnd::How::signaled:
            return "killed by signal " + std::to_string(end.code) + " (" + strsignal(end.code) +
                   ")";
        case ChildEnd::How::timed_out: {
            std::string s = std::to_string(deadline_seconds);
            s.erase(s.find_last_not_of('0') + 1);
            if (!s.empty() && s.back() == '.') s.pop_back();
            return "still running after " + s + " s; stopped";
        }
        case ChildEnd::How::cancelled:
            return "cancelled";
        case ChildEnd::How::not_started:
            return end.error;
    }
    return {};
}

}  // namespace acanthus
