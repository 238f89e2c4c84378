// What bounds the preview server's work: the threads its connections run on, and the programs
// that requests (downloads, debug frames, growth frames) run besides the live render.
#pragma once

#include <httplib.h>

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

namespace acanthus {

// Event streams open at once (a page has one); beyond, 503. Each holds a connection thread
// while it waits, so there are twice as many threads: half always left for requests.
constexpr int kMaxEventStreams = 64;
constexpr std::size_t kMaxConnectionThreads = 2 * kMaxEventStreams;
// Programs run for requests at once, and queued (a download's wait is bounded too).
constexpr int kRequestRunsAtOnce = 2;
constexpr int kRequestRunsQueued = 4;

// The server's task queue. The HTTP library serves a connection on one thread from accept to
// close, so a fixed pool of N threads stops answering once N connections are open: N event
// streams, or N clients that send half a request. Here a connection gets an idle thread, or a
// new one while fewer than `max_threads` run; threads idle for a while end, down to `kept_idle`.
// Connections beyond `max_threads` wait for a thread.
class ConnectionThreads : public httplib::TaskQueue {
  public:
    ConnectionThreads(std::size_t max_threads, std::size_t kept_idle,
                      std::chrono::milliseconds idle_end = std::chrono::seconds(20));
    ~ConnectionThreads() override;
    ConnectionThreads(const ConnectionThreads&) = delete;
    ConnectionThreads& operator=(const ConnectionThreads&) = delete;

    void enqueue(std::function<void()> job) override;
    // Runs the jobs already queued, then waits for every thread to end.
    void shutdown() override;

    std::size_t threads() const;  // running now, busy or idle

  private:
    void work();
    void join_ended();  // holds mutex_

    const std::size_t max_threads_, kept_idle_;
    const std::chrono::milliseconds idle_end_;
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::deque<std::function<void()>> jobs_;
    std::map<std::thread::id, std::thread> threads_;
    std::vector<std::thread::id> ended_;  // threads that left work(), still to be joined
    std::size_t idle_ = 0;
    bool shutdown_ = false;
};

// Programs run on request: at most `running` at once (the machine's cores are the live
// render's first), at most `waiting` more queued; a request beyond those is refused (busy).
class RunSlots {
  public:
    RunSlots(int running, int waiting);

    enum class Outcome { taken, busy, timed_out };
    // Blocks while queued, at most `max_wait`. A taken slot is given back with give_back().
    Outcome take(std::chrono::milliseconds max_wait);
    void give_back();
    int waiting() const;

  private:
    const int max_running_, max_waiting_;
    mutable std::mutex mutex_;
    std::condition_variable freed_;
    int running_ = 0, waiting_ = 0;
};

}  // namespace acanthus
