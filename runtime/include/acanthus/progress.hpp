// A heartbeat for long work inside one rule body (a library laying 100,000 cells, say). The
// runaway-body watchdog counts a report whose `done` grew as progress and restarts the body's
// clock; the progress line shows the latest report ("cells 82,000 / 161,700").
#pragma once

namespace acanthus {

// `what` names the work and must be a string literal: it is kept by pointer and read from other
// threads. `done` counts up; `total` is the expected count, 0 when unknown. Cheap enough to call
// once per item: a few atomic stores.
void report_progress(const char* what, long done, long total = 0) noexcept;

}  // namespace acanthus
