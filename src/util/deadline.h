// deadline.h - a safety net for waits that should end on their own: a function called once a
// time has passed, unless the Deadline is gone first (the fuzzer's cancel of a CAD load after
// a few seconds; a test's held frames let go after a minute).
#pragma once

#include <chrono>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace util {

class Deadline {
  public:
    Deadline(std::chrono::steady_clock::duration after, std::function<void()> then)
        : thread_([this, after, then = std::move(then)] {
              std::unique_lock lock(mutex_);
              if (done_.wait_for(lock, after, [this] { return finished_; })) return;
              try {
                  then();
              } catch (...) {
                  failed_ = std::current_exception(); // for the destructor, which waits
              }
          }) {}
    // Waits for the thread; what `then` threw is thrown here, unless another exception is
    // unwinding the stack already (then it is dropped: two at once would end the process).
    ~Deadline() noexcept(false) {
        {
            const std::lock_guard lock(mutex_);
            finished_ = true;
        }
        done_.notify_one();
        thread_.join();
        if (failed_ && std::uncaught_exceptions() == 0) std::rethrow_exception(failed_);
    }
    Deadline(const Deadline&) = delete;
    Deadline& operator=(const Deadline&) = delete;

  private:
    // Declared before the thread, which uses them from its first instruction.
    std::mutex mutex_;
    std::condition_variable done_;
    bool finished_ = false;
    std::exception_ptr failed_;
    std::thread thread_;
};

} // namespace util
