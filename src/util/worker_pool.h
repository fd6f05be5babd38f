// worker_pool.h - helper processes that do work the parent cannot do on threads (Open
// CASCADE's STEP readers are not thread-safe): each is a program started with a socket on
// file descriptor 3 over which the parent sends jobs and the worker answers, one framed
// message each way at a time. A worker that crashes, is killed or runs out of memory ends
// alone; the parent learns it as an event and decides what its job costs. No worker outlives
// its pool: the destructor kills and reaps them, and each worker asks the kernel to kill it
// when the thread that started it ends (workerStarted). Plain C++, Linux.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <string_view>
#include <sys/types.h>
#include <vector>

namespace util {

// A message: what it is (the sender's numbering) and its bytes.
struct Frame {
    uint32_t kind = 0;
    std::string bytes;
};

// Blocking, whole frames, for the worker's side of the socket (and tests). send: false where
// the other side is gone; receive: false at the end of the stream (or a broken frame).
bool sendFrame(int fd, uint32_t kind, std::string_view bytes);
bool receiveFrame(int fd, Frame& frame);

// The socket a worker talks on, and what it does first: ties its life to the parent's
// starting thread (PR_SET_PDEATHSIG, then a check that the parent is still the one that
// started it), so that a parent killed mid-load takes its workers with it.
constexpr int kWorkerFd = 3;
void workerStarted();

class WorkerPool {
  public:
    // Starts `count` copies of `program` (an absolute path) with `arguments`. Throws
    // std::runtime_error with one line where the program cannot be started.
    WorkerPool(std::string program, std::vector<std::string> arguments, unsigned count);
    ~WorkerPool(); // kills and reaps every worker still running
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    unsigned size() const { return unsigned(workers_.size()); }
    bool running(unsigned worker) const { return workers_[worker].pid > 0; }
    pid_t pid(unsigned worker) const { return workers_[worker].pid; }

    // Sends a whole frame (blocking until the worker has taken it); false where the worker
    // has ended (its end is reported by the next wait()).
    bool send(unsigned worker, uint32_t kind, std::string_view bytes);

    struct Event {
        enum class Kind { Timeout, Message, Ended } kind = Kind::Timeout;
        unsigned worker = 0;
        Frame frame;        // Message
        std::string reason; // Ended: "killed by SIGKILL", "exited with status 2", ...
    };
    // The next message or end of a worker, or Timeout after `timeout`.
    Event wait(std::chrono::milliseconds timeout);

    // Starts the worker again in the same slot after it ended; false where it cannot.
    bool restart(unsigned worker);
    // Kills every worker at once (SIGKILL) and reaps them.
    void killAll();

    // Resident bytes of the running workers together, now (VmRSS).
    uint64_t residentBytes() const;

  private:
    struct Worker {
        pid_t pid = -1;
        int fd = -1;
        std::string received; // bytes of frames not yet whole
        bool ended = false;   // end seen, not yet reported
        std::string reason;
    };
    void start(Worker& worker);
    void reap(Worker& worker);
    bool takeFrame(Worker& worker, Frame& frame);
    std::string program_;
    std::vector<std::string> arguments_;
    std::vector<Worker> workers_;
};

} // namespace util
