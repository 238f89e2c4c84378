// Progress on stderr. On a terminal the line is redrawn in place; elsewhere (--progress into a
// log) each update is its own line, throttled so logs stay short.
#include "program/progress_line.hpp"

#include <unistd.h>

#include <cstdio>

namespace acanthus::detail {

namespace {
constexpr auto automatic_delay = std::chrono::seconds(1);
constexpr auto terminal_interval = std::chrono::milliseconds(100);
constexpr auto log_interval = std::chrono::seconds(1);
}  // namespace

ProgressLine::ProgressLine(std::string program, ProgressMode mode)
    : program_(std::move(program)),
      mode_(mode),
      terminal_(::isatty(STDERR_FILENO) == 1),
      start_(Clock::now()),
      last_(start_) {}

ProgressLine::~ProgressLine() { finish(); }

void ProgressLine::update(long iteration, long elements) {
    if (mode_ == ProgressMode::quiet) return;
    if (mode_ == ProgressMode::automatic && !terminal_) return;
    const auto now = Clock::now();
    if (mode_ == ProgressMode::automatic && now - start_ < automatic_delay) return;
    if (drawn_ && now - last_ < (terminal_ ? terminal_interval : log_interval)) return;
    last_ = now;
    const double seconds = std::chrono::duration<double>(now - start_).count();
    if (terminal_)
        std::fprintf(stderr, "\r%s: iteration %ld, %ld elements, %.1f s\033[K", program_.c_str(),
                     iteration, elements, seconds);
    else
        std::fprintf(stderr, "%s: iteration %ld, %ld elements, %.1f s\n", program_.c_str(),
                     iteration, elements, seconds);
    std::fflush(stderr);
    drawn_ = true;
}

void ProgressLine::finish() {
    if (drawn_ && terminal_) std::fputc('\n', stderr);
    drawn_ = false;
}

}  // namespace acanthus::detail
