// The progress line on stderr: shown on a terminal once a run has taken more than a second,
// always with --progress, never with --quiet. While a rule body reports progress
// (acanthus::report_progress), the line shows its latest report instead.
#pragma once

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

#include "pattern/body_progress.hpp"
#include "program/options.hpp"

namespace acanthus::detail {

class ProgressLine {
  public:
    ProgressLine(std::string program, ProgressMode mode);
    ~ProgressLine();
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    void update(long iteration, long elements);
    // Ends the line (if one was drawn) so later messages start on a fresh line; no body's
    // report is shown after it.
    void finish();

  private:
    using Clock = std::chrono::steady_clock;
    // A thread: the running body's reports, which arrive while update() cannot be called.
    void watch_bodies();
    // With mutex_ held. `body`: a running body's report, or null for the engine's numbers.
    void draw(const BodyProgress* body);

    std::string program_;
    ProgressMode mode_;
    bool terminal_;
    bool drawn_ = false;
    Clock::time_point start_;
    Clock::time_point last_;
    long iteration_ = 0, elements_ = 0;  // the engine's last update
    BodyProgress shown_;                 // the body report on the line; none after an update
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stop_ = false;
    std::thread watcher_;
};

// "82,000": `n` with thousands separators.
std::string with_thousands(long n);
// A body's report as the progress line shows it: "cells 82,000 / 161,700"; "cells 82,000" when
// the total is unknown (0) or already passed.
std::string body_progress_text(const char* what, long done, long total);

}  // namespace acanthus::detail
