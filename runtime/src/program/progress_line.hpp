// The progress line on stderr: shown on a terminal once a run has taken more than a second,
// always with --progress, never with --quiet.
#pragma once

#include <chrono>
#include <string>

#include "program/options.hpp"

namespace acanthus::detail {

class ProgressLine {
  public:
    ProgressLine(std::string program, ProgressMode mode);
    ~ProgressLine();
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    void update(long iteration, long elements);
    // Ends the line (if one was drawn) so later messages start on a fresh line.
    void finish();

  private:
    using Clock = std::chrono::steady_clock;
    std::string program_;
    ProgressMode mode_;
    bool terminal_;
    bool drawn_ = false;
    Clock::time_point start_;
    Clock::time_point last_;
};

}  // namespace acanthus::detail
