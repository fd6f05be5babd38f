// fault_guard.cpp - faults of guarded threads handed to Open CASCADE's error handlers
// (fault_guard.h).

// Open CASCADE's handlers jump only where this is defined, as it was for Debian's build.
#ifndef OCC_CONVERT_SIGNALS
#define OCC_CONVERT_SIGNALS
#endif
#include "scene/cad/fault_guard.h"

#include <atomic>
#include <csignal>
#include <cstring>
#include <mutex>
#include <utility>
#include <vector>

#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>

namespace scene {

namespace {

constexpr int kSignals[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL};

thread_local int tGuards = 0; // guards open on this thread
thread_local int tSignal = 0; // the last fault converted on this thread
std::atomic<int> gGuards{0};  // guards open in the process
struct sigaction gPrevious[NSIG];

// Not ours to handle: behave as the handler installed before ours would have.
void passOn(int signal, siginfo_t* info, void* context) {
    const struct sigaction& previous = gPrevious[signal];
    if ((previous.sa_flags & SA_SIGINFO) && previous.sa_sigaction) {
        previous.sa_sigaction(signal, info, context);
        return;
    }
    if (!(previous.sa_flags & SA_SIGINFO) && previous.sa_handler != SIG_DFL &&
        previous.sa_handler != SIG_IGN) {
        previous.sa_handler(signal);
        return;
    }
    // The default action: a fault repeats on return and now ends the process (core dump
    // included); raise() covers a signal sent rather than caused.
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

void onSignal(int signal, siginfo_t* info, void* context) {
    const bool ours = tGuards > 0 || (gGuards > 0 && Standard_ErrorHandler::IsInTryBlock());
    if (!ours) {
        passOn(signal, info, context);
        return;
    }
    tSignal = signal;
    // The jump leaves the handler for good: let the next fault of this thread in, as Open
    // CASCADE's own handler does (its jump buffers do not keep the signal mask).
    sigset_t mask;
    sigemptyset(&mask);
    sigaddset(&mask, signal);
    sigprocmask(SIG_UNBLOCK, &mask, nullptr);
    Handle(Standard_Failure) failure =
        new Standard_Failure((std::string("idview's fault guard: ") + faultName(signal)).c_str());
    failure->Jump(); // to the innermost Open CASCADE error handler of this thread
}

// Once per process, keeping what was there before (AddressSanitizer's and libFuzzer's
// handlers among them) for the faults that are not ours.
void install() {
    static std::once_flag once;
    std::call_once(once, [] {
        struct sigaction action {};
        action.sa_sigaction = onSignal;
        action.sa_flags = SA_SIGINFO | SA_ONSTACK;
        sigemptyset(&action.sa_mask);
        for (int signal : kSignals) sigaction(signal, &action, &gPrevious[signal]);
    });
}

// An alternate signal stack for this thread while the guard is open, unless it has one
// (AddressSanitizer gives every thread its own), so that a stack overflow can be caught.
class AltStack {
  public:
    AltStack() {
        stack_t current{};
        if (sigaltstack(nullptr, &current) != 0 || !(current.ss_flags & SS_DISABLE)) return;
        memory_.resize(256 * 1024);
        stack_t mine{};
        mine.ss_sp = memory_.data();
        mine.ss_size = memory_.size();
        if (sigaltstack(&mine, &previous_) == 0) owned_ = true;
    }
    ~AltStack() {
        if (owned_) sigaltstack(&previous_, nullptr);
    }
    AltStack(const AltStack&) = delete;
    AltStack& operator=(const AltStack&) = delete;

  private:
    std::vector<char> memory_;
    stack_t previous_{};
    bool owned_ = false;
};

struct Open {
    Open() {
        ++tGuards;
        ++gGuards;
    }
    ~Open() {
        --tGuards;
        --gGuards;
    }
};

} // namespace

int runGuarded(const std::function<void()>& body) {
    install();
    const AltStack altStack;
    const Open open;
    const int before = tSignal;
    try {
        // Open CASCADE's error handler: a converted fault jumps here and is thrown again as
        // the C++ exception caught below, so the handler list it keeps stays whole.
        OCC_CATCH_SIGNALS
        body();
    } catch (const Standard_Failure&) {
        // A fault converted by this guard, or an exception of `body` to pass on.
        if (tSignal != before && tSignal != 0) {
            const int signal = tSignal;
            tSignal = before;
            return signal;
        }
        throw;
    }
    tSignal = before; // faults Open CASCADE handled on its own do not count
    return 0;
}

const char* faultName(int signal) {
    static constexpr std::pair<int, const char*> names[] = {{SIGSEGV, "segmentation fault"},
                                                            {SIGBUS, "bus error"},
                                                            {SIGFPE, "arithmetic fault"},
                                                            {SIGILL, "illegal instruction"}};
    for (const auto& [number, name] : names)
        if (number == signal) return name;
    return "fault";
}

} // namespace scene
