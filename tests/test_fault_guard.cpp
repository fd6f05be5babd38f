// test_fault_guard.cpp - faults on a guarded thread come back as a signal number, and faults
// anywhere else still end the process as they did before.
// As Open CASCADE was built: its handlers, opened by OCC_CATCH_SIGNALS, take jumps.
#ifndef OCC_CONVERT_SIGNALS
#define OCC_CONVERT_SIGNALS
#endif
#include <atomic>
#include <csignal>
#include <stdexcept>
#include <sys/mman.h>
#include <thread>
#include <unistd.h>

#include <gtest/gtest.h>

#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>

#include "scene/cad/fault_guard.h"

namespace {

// A write to a page the process may not touch: a real SIGSEGV, not one sent by raise().
void touchForbiddenPage() {
    const long page = sysconf(_SC_PAGESIZE);
    void* p = mmap(nullptr, size_t(page), PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    ASSERT_NE(p, MAP_FAILED);
    *static_cast<volatile char*>(p) = 1;
}

// Recursion no compiler can fold, to run out of stack.
int deep(int n) {
    volatile char pad[4096];
    pad[0] = char(n);
    if (n > 1'000'000'000) return pad[0];
    return deep(n + 1) + pad[0];
}

bool died(int status) {
    // Killed by the signal, or (under AddressSanitizer) reported and exited with an error.
    return WIFSIGNALED(status) || (WIFEXITED(status) && WEXITSTATUS(status) != 0);
}

} // namespace

TEST(FaultGuard, AFaultInTheBodyReturnsItsSignal) {
    EXPECT_EQ(scene::runGuarded([] {}), 0);
    EXPECT_EQ(scene::runGuarded(touchForbiddenPage), SIGSEGV);
    EXPECT_EQ(scene::runGuarded([] { std::raise(SIGFPE); }), SIGFPE);
    EXPECT_EQ(scene::runGuarded([] { std::raise(SIGBUS); }), SIGBUS);
    // The thread goes on as before: the guard can be used again, and the signal mask is back.
    EXPECT_EQ(scene::runGuarded(touchForbiddenPage), SIGSEGV);
    sigset_t blocked;
    ASSERT_EQ(sigprocmask(SIG_BLOCK, nullptr, &blocked), 0);
    EXPECT_FALSE(sigismember(&blocked, SIGSEGV));
    EXPECT_STREQ(scene::faultName(SIGSEGV), "segmentation fault");
}

TEST(FaultGuard, AStackOverflowIsCaught) {
    std::atomic<int> signal{-1};
    // On a thread of its own, which has no alternate signal stack until the guard gives it one.
    std::thread([&] { signal = scene::runGuarded([] { deep(0); }); }).join();
    EXPECT_EQ(signal, SIGSEGV);
}

TEST(FaultGuard, NestedGuardsAndExceptions) {
    int inner = -1;
    const int outer = scene::runGuarded([&] {
        inner = scene::runGuarded(touchForbiddenPage);
        touchForbiddenPage(); // the outer guard's again
    });
    EXPECT_EQ(inner, SIGSEGV);
    EXPECT_EQ(outer, SIGSEGV);
    EXPECT_THROW(scene::runGuarded([] { throw std::runtime_error("thrown"); }), std::runtime_error);
    // The exception left the guard closed: a fault now is not caught (see the next test).
}

TEST(FaultGuardDeathTest, FaultsOutsideAGuardStillEndTheProcess) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    // After a guard was used (its handler is installed) on this thread, and on another thread
    // while this one sits in a guard.
    EXPECT_EXIT(
        {
            scene::runGuarded([] {});
            touchForbiddenPage();
        },
        died, "");
    EXPECT_EXIT(scene::runGuarded([] { std::thread(touchForbiddenPage).join(); }), died, "");
    EXPECT_EXIT(
        {
            try {
                scene::runGuarded([] { throw std::runtime_error("thrown"); });
            } catch (const std::runtime_error&) {
            }
            touchForbiddenPage();
        },
        died, "");
}

// Open CASCADE's mesher runs faces on worker threads inside its own error handlers: while a
// guard is open anywhere, a fault there goes to that handler, as Open CASCADE means it to.
TEST(FaultGuard, AFaultInsideAnOpenCascadeHandlerOnAnotherThreadGoesToIt) {
    bool caught = false;
    const int signal = scene::runGuarded([&] {
        std::thread([&] {
            try {
                OCC_CATCH_SIGNALS
                touchForbiddenPage();
            } catch (const Standard_Failure&) {
                caught = true;
            }
        }).join();
    });
    EXPECT_EQ(signal, 0);
    EXPECT_TRUE(caught);
}
