#include "server/limits.hpp"

#include <thread>

namespace acanthus {

ConnectionThreads::ConnectionThreads(std::size_t max_threads, std::size_t kept_idle,
                                     std::chrono::milliseconds idle_end)
    : max_threads_(max_threads < 1 ? 1 : max_threads), kept_idle_(kept_idle), idle_end_(idle_end) {}

ConnectionThreads::~ConnectionThreads() { shutdown(); }

void ConnectionThreads::enqueue(std::function<void()> job) {
    std::lock_guard lock(mutex_);
    join_ended();
    jobs_.push_back(std::move(job));
    // More jobs waiting than idle threads to take them: one more thread, within the bound.
    if (jobs_.size() > idle_ && threads_.size() - ended_.size() < max_threads_ && !shutdown_) {
        std::thread thread([this] { work(); });
        const std::thread::id id = thread.get_id();
        threads_.emplace(id, std::move(thread));
    }
    wake_.notify_one();
}

void ConnectionThreads::join_ended() {
    // An ended thread takes no lock after saying so: joining it here cannot wait on us.
    for (const std::thread::id id : ended_) {
        auto it = threads_.find(id);
        if (it == threads_.end()) continue;
        it->second.join();
        threads_.erase(it);
    }
    ended_.clear();
}

void ConnectionThreads::work() {
    std::unique_lock lock(mutex_);
    for (;;) {
        ++idle_;
        const bool woken =
            wake_.wait_for(lock, idle_end_, [&] { return shutdown_ || !jobs_.empty(); });
        --idle_;
        if (jobs_.empty()) {
            if (shutdown_ || (!woken && idle_ >= kept_idle_)) break;
            continue;
        }
        std::function<void()> job = std::move(jobs_.front());
        jobs_.pop_front();
        lock.unlock();
        job();
        job = nullptr;  // what the job holds goes before the thread counts as ended
        lock.lock();
    }
    ended_.push_back(std::this_thread::get_id());
}

void ConnectionThreads::shutdown() {
    std::map<std::thread::id, std::thread> threads;
    {
        std::lock_guard lock(mutex_);
        shutdown_ = true;
        wake_.notify_all();
        threads.swap(threads_);
        ended_.clear();
    }
    for (auto& [id, thread] : threads) thread.join();
    std::lock_guard lock(mutex_);
    ended_.clear();  // the ids the joined threads left on their way out
}

std::size_t ConnectionThreads::threads() const {
    std::lock_guard lock(mutex_);
    return threads_.size() - ended_.size();
}

RunSlots::RunSlots(int running, int waiting) : max_running_(running), max_waiting_(waiting) {}

RunSlots::Outcome RunSlots::take(std::chrono::milliseconds max_wait) {
    std::unique_lock lock(mutex_);
    if (running_ < max_running_) {
        ++running_;
        return Outcome::taken;
    }
    if (waiting_ >= max_waiting_) return Outcome::busy;
    ++waiting_;
    const bool freed = freed_.wait_for(lock, max_wait, [&] { return running_ < max_running_; });
    --waiting_;
    if (!freed) return Outcome::timed_out;
    ++running_;
    return Outcome::taken;
}

void RunSlots::give_back() {
    std::lock_guard lock(mutex_);
    --running_;
    freed_.notify_one();
}

int RunSlots::waiting() const {
    std::lock_guard lock(mutex_);
    return waiting_;
}

}  // namespace acanthus
