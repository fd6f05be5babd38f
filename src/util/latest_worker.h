// latest_worker.h - one worker thread for slow answers a UI asks for again and again (the
// Inspect panel's Open CASCADE work): only the newest question matters. A newer job supersedes
// the one before it: a job not started yet is dropped, a running one is told to stop (its
// `cancelled` flag, which it checks between its steps) and its result, should it still come,
// is thrown away. The UI polls take() each frame and never waits; `landed` (called on the
// worker thread) wakes a UI loop that rests. A job's exception is handed to the UI thread by
// take(), as if the job had run there. The destructor cancels and joins. Plain C++.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

namespace util {

template <typename Result>
class LatestWorker {
  public:
    // Returns nullopt where it stopped because it was cancelled.
    using Job = std::function<std::optional<Result>(const std::atomic<bool>& cancelled)>;

    // `landed` runs on the worker thread, under the worker's lock, each time a result lands:
    // it must be short and must not call this worker (waking a UI loop is what it is for).
    explicit LatestWorker(std::function<void()> landed = {})
        : landed_(std::move(landed)), thread_([this] { loop(); }) {}
    ~LatestWorker() {
        {
            const std::lock_guard lock(mutex_);
            stop_ = true;
            if (running_) running_->store(true);
        }
        wake_.notify_all();
        thread_.join(); // at most the running job's current step
    }
    LatestWorker(const LatestWorker&) = delete;
    LatestWorker& operator=(const LatestWorker&) = delete;

    // The job to run next, superseding any before it.
    void submit(Job job) {
        {
            const std::lock_guard lock(mutex_);
            supersede();
            next_ = std::move(job);
            wanted_ = ++submitted_;
        }
        wake_.notify_all();
    }
    // Nothing is wanted any more: the queued job is dropped, the running one cancelled.
    void cancel() {
        const std::lock_guard lock(mutex_);
        supersede();
        wanted_ = 0;
    }
    // The newest job's result, once; nullopt while it runs (or when none is wanted). Rethrows
    // what the job threw.
    std::optional<Result> take() {
        const std::lock_guard lock(mutex_);
        if (failure_) std::rethrow_exception(std::exchange(failure_, nullptr));
        return std::exchange(result_, std::nullopt);
    }
    // Whether the newest job's result (or failure) is waiting for take().
    bool landed() const {
        const std::lock_guard lock(mutex_);
        return result_ || failure_;
    }
    // Whether the newest job is queued or running: its result has not landed yet.
    bool pending() const {
        const std::lock_guard lock(mutex_);
        return wanted_ != 0;
    }
    // Tests: jobs wait before they start until released (the destructor releases them).
    void hold(bool held) {
        {
            const std::lock_guard lock(mutex_);
            held_ = held;
        }
        wake_.notify_all();
    }
    // Tests and batch callers, never a frame: waits until the newest job's result is there.
    void wait() {
        std::unique_lock lock(mutex_);
        done_.wait(lock, [this] { return wanted_ == 0; });
    }

  private:
    // Under mutex_: the queued job goes, the running one is told to stop, no result stays.
    void supersede() {
        next_ = nullptr;
        result_.reset();
        failure_ = nullptr;
        if (running_) running_->store(true);
    }

    void loop() {
        std::unique_lock lock(mutex_);
        for (;;) {
            wake_.wait(lock, [this] { return stop_ || (next_ && !held_); });
            if (stop_) return;
            Job job = std::exchange(next_, nullptr);
            const uint64_t ticket = wanted_;
            auto cancelled = std::make_shared<std::atomic<bool>>(false);
            running_ = cancelled;
            lock.unlock();
            std::optional<Result> result;
            std::exception_ptr failure;
            try {
                result = job(*cancelled);
            } catch (...) {
                failure = std::current_exception();
            }
            job = nullptr; // what it holds (a scene's copy) goes on this thread, not the UI's
            lock.lock();
            running_.reset();
            // A job superseded (or cancelled) while it ran keeps its result to itself.
            if (ticket != wanted_) continue;
            result_ = std::move(result);
            failure_ = failure;
            wanted_ = 0;            // landed (a job may give no answer: nothing to take then)
            if (landed_) landed_(); // before wait() returns; under the lock, so it is short
            done_.notify_all();
        }
    }

    std::function<void()> landed_;
    mutable std::mutex mutex_;
    std::condition_variable wake_, done_;
    Job next_;
    std::optional<Result> result_;
    std::exception_ptr failure_;
    std::shared_ptr<std::atomic<bool>> running_; // the running job's cancel flag
    uint64_t submitted_ = 0, wanted_ = 0;        // wanted_: the newest job's number, 0 none
    bool held_ = false, stop_ = false;
    std::thread thread_; // last: starts once everything above is there
};

} // namespace util
