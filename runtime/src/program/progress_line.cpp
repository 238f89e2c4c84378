// Progress on stderr. On a terminal the line is redrawn in place; elsewhere (--progress into a
// log) each update is its own line, throttled so logs stay short. The engine's updates come from
// the growth loop; a long body's reports are polled by a thread of the line's own, since the
// loop is stuck in that body meanwhile.
#include "program/progress_line.hpp"

#include <unistd.h>

#include <cstdio>

#include "pattern/running_body.hpp"

namespace acanthus::detail {

namespace {
constexpr auto automatic_delay = std::chrono::seconds(1);
constexpr auto terminal_interval = std::chrono::milliseconds(100);
constexpr auto log_interval = std::chrono::seconds(1);

bool same_report(const BodyProgress& a, const BodyProgress& b) {
    return a.what == b.what && a.done == b.done && a.total == b.total;
}
}  // namespace

std::string with_thousands(long n) {
    // Through the magnitude as unsigned: -LONG_MIN does not fit in a long.
    const auto bits = static_cast<unsigned long>(n);
    const std::string digits = std::to_string(n < 0 ? 0UL - bits : bits);
    std::string out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return n < 0 ? "-" + out : out;
}

std::string body_progress_text(const char* what, long done, long total) {
    std::string text = what ? what : "";
    if (!text.empty()) text += ' ';
    text += with_thousands(done);
    if (total > 0 && total >= done) text += " / " + with_thousands(total);
    return text;
}

ProgressLine::ProgressLine(std::string program, ProgressMode mode)
    : program_(std::move(program)),
      mode_(mode),
      terminal_(::isatty(STDERR_FILENO) == 1),
      start_(Clock::now()),
      last_(start_) {
    const bool shown =
        mode_ == ProgressMode::forced || (mode_ == ProgressMode::automatic && terminal_);
    if (shown) watcher_ = std::thread([this] { watch_bodies(); });
}

ProgressLine::~ProgressLine() { finish(); }

void ProgressLine::update(long iteration, long elements) {
    if (mode_ == ProgressMode::quiet) return;
    if (mode_ == ProgressMode::automatic && !terminal_) return;
    const std::lock_guard<std::mutex> lock(mutex_);
    if (stop_) return;
    iteration_ = iteration;
    elements_ = elements;
    draw(nullptr);
}

void ProgressLine::watch_bodies() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!wake_.wait_for(lock, terminal_interval, [this] { return stop_; })) {
        const BodyProgress body = running_body_progress();
        // Between bodies, and in bodies that do not report, the engine's updates draw the line.
        if (!body.what || same_report(body, shown_)) continue;
        draw(&body);
    }
}

void ProgressLine::draw(const BodyProgress* body) {
    const auto now = Clock::now();
    if (mode_ == ProgressMode::automatic && now - start_ < automatic_delay) return;
    if (drawn_ && now - last_ < (terminal_ ? terminal_interval : log_interval)) return;
    last_ = now;
    const double seconds = std::chrono::duration<double>(now - start_).count();
    char numbers[128];
    if (body)
        std::snprintf(numbers, sizeof numbers, "%.1f s", seconds);
    else
        std::snprintf(numbers, sizeof numbers, "iteration %ld, %ld elements, %.1f s", iteration_,
                      elements_, seconds);
    const std::string text =
        body ? body_progress_text(body->what, body->done, body->total) + ", " + numbers : numbers;
    if (terminal_) {
        std::fprintf(stderr, "\r%s: %s\033[K", program_.c_str(), text.c_str());
        set_fatal_exit_line_open(true);  // a runaway body's message goes below the line
    } else
        std::fprintf(stderr, "%s: %s\n", program_.c_str(), text.c_str());
    std::fflush(stderr);
    drawn_ = true;
    shown_ = body ? *body : BodyProgress{};
}

void ProgressLine::finish() {
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    if (watcher_.joinable()) watcher_.join();
    const std::lock_guard<std::mutex> lock(mutex_);
    if (drawn_ && terminal_) {
        std::fputc('\n', stderr);
        set_fatal_exit_line_open(false);
    }
    drawn_ = false;
}

}  // namespace acanthus::detail
