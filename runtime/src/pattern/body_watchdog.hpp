// A thread that ends the run when user code runs away: one body running longer than the
// per-call limit, or still running a grace second after --time-limit. Exit 3 naming the rule
// and its line, no output left behind (running_body.hpp).
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

    // `call_limit`: longest one body may run (0: no limit). `time_limit`: the run's
    // --time-limit, counted from now (0: none).
    BodyWatchdog(double call_limit, double time_limit);
    ~BodyWatchdog();
    BodyWatchdog(const BodyWatchdog&) = delete;
    BodyWatchdog& operator=(const BodyWatchdog&) = delete;

  private:
    void watch();

    double call_limit_;
    double time_limit_;
    std::string call_message_;  // preformatted: the watchdog thread does not allocate to fire
    std::string time_message_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stop_ = false;
    std::thread thread_;
};

}  // namespace acanthus::detail
