// deadline.h - a safety net for waits that should end on their own: a function called once a
// time has passed, unless the Deadline is gone first (the fuzzer's cancel of a CAD load after
// a few seconds; a test's held frames let go after a minute).
#pragma once

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

namespace util {

class Deadline {
  public:
    Deadline(std::chrono::steady_clock::duration after, std::function<void()> then)
        : thread_([this, after, then = std::move(then)] {
              std::unique_lock lock(mutex_);
              if (!done_.wait_for(lock, after, [this] { return finished_; })) then();
          }) {}
    ~Deadline() {
        {
            const std::lock_guard lock(mutex_);
            finished_ = true;
        }
        done_.notify_one();
        thread_.join();
    }
    Deadline(const Deadline&) = delete;
    Deadline& operator=(const Deadline&) = delete;

  private:
    // Declared before the thread, which uses them from its first instruction.
    std::mutex mutex_;
    std::condition_variable done_;
    bool finished_ = false;
    std::thread thread_;
};

} // namespace util
