// A thread that ends the run when user code runs away: one body making no progress for the
// per-call limit, or still running a grace second after --time-limit. A body makes progress by
// reporting a grown `done` (acanthus::report_progress); one that never reports has the limit
// for the whole call. Exit 3 naming the rule and its line, no output left behind
// (running_body.hpp).
#pragma once

#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace acanthus::detail {

class BodyWatchdog {
  public:
    static constexpr double kDefaultCallLimit = 10;  // seconds
    static constexpr double kTimeLimitGrace = 1;     // seconds after --time-limit

    // `call_limit`: longest one body may run without progress (0: no limit). `time_limit`: the
    // run's --time-limit, counted from now (0: none).
    BodyWatchdog(double call_limit, double time_limit);
    ~BodyWatchdog();
    BodyWatchdog(const BodyWatchdog&) = delete;
    BodyWatchdog& operator=(const BodyWatchdog&) = delete;

  private:
    void watch();

    double call_limit_;
    double time_limit_;
    // Preformatted: the watchdog thread does not allocate to fire.
    std::string call_message_;     // the body never reported progress
    std::string stalled_message_;  // it reported, but `done` stopped growing
    std::string time_message_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stop_ = false;
    std::thread thread_;
};

}  // namespace acanthus::detail
