// worker_pool.cpp - helper processes on a socket each (worker_pool.h).
#include "util/worker_pool.h"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <stdexcept>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

#include "util/memory.h"

extern char** environ;

namespace util {
namespace {

// A frame's head: kind (u32) and size (u64), host byte order (both ends are this machine).
constexpr size_t kHead = sizeof(uint32_t) + sizeof(uint64_t);
// Far beyond any job or result; a broken head is not taken for a length to allocate.
constexpr uint64_t kMaxFrame = uint64_t(1) << 34;

bool sendAll(int fd, const char* data, size_t size) {
    while (size > 0) {
        // MSG_NOSIGNAL: a worker that died makes this fail with EPIPE, never a SIGPIPE that
        // would end the parent.
        const ssize_t sent = ::send(fd, data, size, MSG_NOSIGNAL);
        if (sent < 0 && errno == EINTR) continue;
        if (sent <= 0) return false;
        data += sent;
        size -= size_t(sent);
    }
    return true;
}

bool receiveAll(int fd, char* data, size_t size) {
    while (size > 0) {
        const ssize_t got = ::recv(fd, data, size, 0);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) return false;
        data += got;
        size -= size_t(got);
    }
    return true;
}

std::string head(uint32_t kind, uint64_t size) {
    std::string bytes(kHead, '\0');
    std::memcpy(bytes.data(), &kind, sizeof kind);
    std::memcpy(bytes.data() + sizeof kind, &size, sizeof size);
    return bytes;
}

std::string endReason(int status) {
    if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
    if (WIFSIGNALED(status)) {
        const int signal = WTERMSIG(status);
        const char* name = sigabbrev_np(signal);
        const char* text = strsignal(signal);
        return std::string("killed by SIG") + (name ? name : std::to_string(signal).c_str()) +
               (text ? std::string(" (") + text + ")" : std::string());
    }
    return "ended";
}

} // namespace

bool sendFrame(int fd, uint32_t kind, std::string_view bytes) {
    const std::string h = head(kind, bytes.size());
    return sendAll(fd, h.data(), h.size()) && sendAll(fd, bytes.data(), bytes.size());
}

bool receiveFrame(int fd, Frame& frame) {
    char h[kHead];
    if (!receiveAll(fd, h, kHead)) return false;
    uint64_t size = 0;
    std::memcpy(&frame.kind, h, sizeof frame.kind);
    std::memcpy(&size, h + sizeof frame.kind, sizeof size);
    if (size > kMaxFrame) return false;
    frame.bytes.resize(size);
    return receiveAll(fd, frame.bytes.data(), size);
}

void workerStarted() {
    // Killed with the thread that started it (the parent's loading thread, which waits for
    // its workers), and at once if that already happened before this line.
    const pid_t parent = getppid();
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent || parent == 1) _exit(1);
    std::signal(SIGPIPE, SIG_IGN); // a parent gone mid-answer: the send fails, no signal
}

WorkerPool::WorkerPool(std::string program, std::vector<std::string> arguments, unsigned count)
    : program_(std::move(program)), arguments_(std::move(arguments)), workers_(count) {
    for (Worker& worker : workers_) start(worker);
}

WorkerPool::~WorkerPool() {
    killAll();
}

void WorkerPool::start(Worker& worker) {
    int sockets[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sockets) != 0)
        throw std::runtime_error(std::string("cannot make a socket for a worker: ") +
                                 std::strerror(errno));
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    // The worker's socket becomes fd 3 (dup2 clears close-on-exec); its stdout, where Open
    // CASCADE may print, goes nowhere; stderr stays, for a sanitizer's report.
    posix_spawn_file_actions_adddup2(&actions, sockets[1], kWorkerFd);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    std::vector<char*> argv{const_cast<char*>(program_.c_str())};
    for (std::string& argument : arguments_) argv.push_back(argument.data());
    argv.push_back(nullptr);
    pid_t pid = -1;
    const int error = posix_spawn(&pid, program_.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    close(sockets[1]);
    if (error != 0) {
        close(sockets[0]);
        throw std::runtime_error("cannot start " + program_ + ": " + std::strerror(error));
    }
    worker = Worker{};
    worker.pid = pid;
    worker.fd = sockets[0];
}

bool WorkerPool::send(unsigned index, uint32_t kind, std::string_view bytes) {
    Worker& worker = workers_[index];
    return worker.pid > 0 && !worker.ended && sendFrame(worker.fd, kind, bytes);
}

bool WorkerPool::takeFrame(Worker& worker, Frame& frame) {
    if (worker.received.size() < kHead) return false;
    uint64_t size = 0;
    std::memcpy(&frame.kind, worker.received.data(), sizeof frame.kind);
    std::memcpy(&size, worker.received.data() + sizeof frame.kind, sizeof size);
    if (size > kMaxFrame) {
        worker.ended = true;
        worker.reason = "sent a broken message";
        return false;
    }
    if (worker.received.size() - kHead < size) return false;
    frame.bytes.assign(worker.received, kHead, size);
    worker.received.erase(0, kHead + size);
    return true;
}

void WorkerPool::reap(Worker& worker) {
    if (worker.fd >= 0) close(worker.fd);
    worker.fd = -1;
    if (worker.pid <= 0) return;
    int status = 0;
    // Its socket closed because it ended; give it a moment to be a zombie, then make sure.
    pid_t done = 0;
    for (int i = 0; i < 100 && (done = waitpid(worker.pid, &status, WNOHANG)) == 0; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    if (done == 0) {
        kill(worker.pid, SIGKILL);
        done = waitpid(worker.pid, &status, 0);
    }
    if (worker.reason.empty()) worker.reason = done > 0 ? endReason(status) : "ended";
    worker.pid = -1;
}

WorkerPool::Event WorkerPool::wait(std::chrono::milliseconds timeout) {
    const auto until = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        for (unsigned i = 0; i < workers_.size(); ++i) {
            Worker& worker = workers_[i];
            Event event;
            event.worker = i;
            if (worker.pid > 0 && takeFrame(worker, event.frame)) {
                event.kind = Event::Kind::Message;
                return event;
            }
            if (worker.pid > 0 && worker.ended) {
                reap(worker);
                event.kind = Event::Kind::Ended;
                event.reason = worker.reason;
                return event;
            }
        }
        std::vector<pollfd> fds;
        std::vector<unsigned> of;
        for (unsigned i = 0; i < workers_.size(); ++i)
            if (workers_[i].pid > 0) {
                fds.push_back({workers_[i].fd, POLLIN, 0});
                of.push_back(i);
            }
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            until - std::chrono::steady_clock::now());
        if (fds.empty() || left.count() <= 0) return {};
        const int ready = poll(fds.data(), fds.size(), int(left.count()));
        if (ready < 0 && errno != EINTR) return {};
        for (size_t k = 0; k < fds.size(); ++k) {
            if (!(fds[k].revents & (POLLIN | POLLHUP | POLLERR))) continue;
            Worker& worker = workers_[of[k]];
            char chunk[1 << 16];
            for (;;) { // what the socket holds now
                const ssize_t got = ::recv(worker.fd, chunk, sizeof chunk, MSG_DONTWAIT);
                if (got > 0) {
                    worker.received.append(chunk, size_t(got));
                    continue;
                }
                if (got == 0 || (errno != EINTR && errno != EAGAIN && errno != EWOULDBLOCK))
                    worker.ended = true;
                if (got < 0 && errno == EINTR) continue;
                break;
            }
        }
    }
}

bool WorkerPool::restart(unsigned index) {
    Worker& worker = workers_[index];
    if (worker.pid > 0) return true;
    try {
        start(worker);
    } catch (const std::runtime_error&) {
        return false;
    }
    return true;
}

void WorkerPool::killAll() {
    for (Worker& worker : workers_)
        if (worker.pid > 0) kill(worker.pid, SIGKILL);
    for (Worker& worker : workers_) {
        if (worker.pid > 0) {
            int status = 0;
            waitpid(worker.pid, &status, 0);
            worker.pid = -1;
        }
        if (worker.fd >= 0) close(worker.fd);
        worker.fd = -1;
    }
}

uint64_t WorkerPool::residentBytes() const {
    uint64_t total = 0;
    for (const Worker& worker : workers_)
        if (worker.pid > 0) total += util::residentBytes(worker.pid);
    return total;
}

} // namespace util
