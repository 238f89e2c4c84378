// The latest acanthus::report_progress() of the running body: the watchdog takes a grown `done`
// as progress, the progress line shows it.
#pragma once

namespace acanthus::detail {

struct BodyProgress {
    const char* what = nullptr;  // null: no report yet
    long done = 0;
    long total = 0;  // 0: unknown
};

// The latest report made during body call `sequence` (a RunningBody::sequence() value); `what`
// is null when that call has not reported. Lock-free: for the watchdog's and other threads.
BodyProgress body_progress(unsigned long sequence) noexcept;

// The latest report of the body running now; `what` is null between bodies and while the
// running body has not reported.
BodyProgress running_body_progress() noexcept;

}  // namespace acanthus::detail
