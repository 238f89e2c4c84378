// The runaway-body watchdog (see body_watchdog.hpp).
#include "pattern/body_watchdog.hpp"

#include <chrono>
#include <sstream>

#include "pattern/body_progress.hpp"
#include "pattern/running_body.hpp"

namespace acanthus::detail {

namespace {

using Clock = std::chrono::steady_clock;
constexpr auto kPoll = std::chrono::milliseconds(50);

std::string seconds_text(double s) {
    std::ostringstream out;
    out << s << " s";
    return out.str();
}

double seconds_between(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
}

}  // namespace

BodyWatchdog::BodyWatchdog(double call_limit, double time_limit)
    : call_limit_(call_limit),
      time_limit_(time_limit),
      call_message_("still running after " + seconds_text(call_limit) +
                    " (an endless loop?); stopped by the per-call limit (--body-time-limit)"),
      stalled_message_("still running, with no progress reported for " + seconds_text(call_limit) +
                       " (an endless loop?); stopped by the per-call limit (--body-time-limit)"),
      time_message_("still running " + seconds_text(kTimeLimitGrace) +
                    " after the --time-limit of " + seconds_text(time_limit) +
                    " (an endless loop?); stopped") {
    if (call_limit_ > 0 || time_limit_ > 0) thread_ = std::thread([this] { watch(); });
}

BodyWatchdog::~BodyWatchdog() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    if (thread_.joinable()) thread_.join();
}

void BodyWatchdog::watch() {
    const Clock::time_point start = Clock::now();
    unsigned long watched = 0;
    bool watching = false;
    Clock::time_point since = start;  // the watched body's start or its last progress
    bool reported = false;            // the watched body has reported
    long last_done = 0;               // its `done` at the previous look
    std::unique_lock<std::mutex> lock(mutex_);
    while (!wake_.wait_for(lock, kPoll, [this] { return stop_; })) {
        const unsigned long before = RunningBody::sequence();
        const char* label = RunningBody::label();
        const BodyProgress progress = body_progress(before);
        const Clock::time_point now = Clock::now();
        if (!label || RunningBody::sequence() != before) {
            watching = false;
            continue;
        }
        if (!watching || watched != before) {
            watching = true;
            watched = before;
            since = now;
            reported = progress.what != nullptr;
            last_done = progress.done;
            continue;
        }
        // The same body has been running since `since` (at least one poll). Its first report, or
        // a `done` grown since the last look, is progress: the per-call clock starts again.
        if (progress.what) {
            if (!reported || progress.done > last_done) since = now;
            reported = true;
            last_done = progress.done;
        }
        if (call_limit_ > 0 && seconds_between(since, now) >= call_limit_)
            fatal_body_exit(label, reported ? stalled_message_.c_str() : call_message_.c_str());
        if (time_limit_ > 0 && seconds_between(start, now) >= time_limit_ + kTimeLimitGrace)
            fatal_body_exit(label, time_message_.c_str());
    }
}

}  // namespace acanthus::detail
