// The running body's heartbeat (see body_progress.hpp and <acanthus/progress.hpp>). A report is
// a handful of relaxed stores, so libraries may report once per cell; readers poll.
#include "pattern/body_progress.hpp"

#include <acanthus/progress.hpp>
#include <atomic>

#include "pattern/running_body.hpp"

namespace acanthus {

namespace {

std::atomic<const char*> g_what{nullptr};
std::atomic<long> g_done{0};
std::atomic<long> g_total{0};
// The body call (RunningBody::sequence()) that made the report; stored last, with release, so
// a reader that sees its own call here sees that call's values (or newer ones).
std::atomic<unsigned long> g_reporter{0};

}  // namespace

void report_progress(const char* what, long done, long total) noexcept {
    g_what.store(what ? what : "", std::memory_order_relaxed);
    g_done.store(done, std::memory_order_relaxed);
    g_total.store(total, std::memory_order_relaxed);
    g_reporter.store(detail::RunningBody::sequence(), std::memory_order_release);
}

namespace detail {

BodyProgress body_progress(unsigned long sequence) noexcept {
    if (g_reporter.load(std::memory_order_acquire) != sequence) return {};
    return {g_what.load(std::memory_order_relaxed), g_done.load(std::memory_order_relaxed),
            g_total.load(std::memory_order_relaxed)};
}

BodyProgress running_body_progress() noexcept {
    const unsigned long sequence = RunningBody::sequence();
    if (!RunningBody::label()) return {};
    const BodyProgress progress = body_progress(sequence);
    // A body that started meanwhile has not reported yet.
    return RunningBody::sequence() == sequence ? progress : BodyProgress{};
}

}  // namespace detail

}  // namespace acanthus
