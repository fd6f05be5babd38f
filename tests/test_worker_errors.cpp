// test_worker_errors.cpp - what a worker thread throws reaches the thread that waits for it:
// forEachTask's workers (levels of detail, CAD levels) and util::Deadline's thread. Before, a
// std::bad_alloc on a worker ended the process (std::terminate), so these tests crashed.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <new>
#include <stdexcept>
#include <thread>

#include "scene/lod_policy.h"
#include "util/deadline.h"

TEST(WorkerErrors, ABadAllocOnAWorkerReachesTheCallerAndStopsTheTasks) {
    if (std::thread::hardware_concurrency() < 2) GTEST_SKIP() << "one hardware thread: no worker";
    const std::thread::id caller = std::this_thread::get_id();
    const size_t count = 10000;
    std::atomic<size_t> ran{0};
    std::atomic<bool> thrown{false};
    auto task = [&](size_t) {
        ++ran;
        if (std::this_thread::get_id() != caller) {
            thrown = true;
            throw std::bad_alloc();
        }
        // The caller leaves the tasks to the workers until one has thrown.
        for (int wait = 0; wait < 2000 && !thrown; ++wait)
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
    };
    EXPECT_THROW(scene::forEachTask(count, task), std::bad_alloc);
    EXPECT_TRUE(thrown);
    EXPECT_LT(ran.load(), count); // no task begun after the throw
}

TEST(WorkerErrors, TheFirstErrorOfTheCallersOwnTasksIsRethrownToo) {
    std::atomic<size_t> ran{0};
    auto task = [&](size_t i) {
        ++ran;
        if (i == 3) throw std::runtime_error("task 3");
    };
    try {
        scene::forEachTask(100, task);
        ADD_FAILURE() << "nothing thrown";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "task 3");
    }
    // Progress that throws (a cancelled load) stops the tasks as well.
    EXPECT_THROW(scene::forEachTask(
                     100, [](size_t) {}, [](double) { throw std::runtime_error("cancelled"); }),
                 std::runtime_error);
}

TEST(WorkerErrors, ADeadlineThatThrowsThrowsWhereItIsWaitedFor) {
    auto wait = [] {
        const util::Deadline deadline(std::chrono::milliseconds(1),
                                      [] { throw std::runtime_error("deadline"); });
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    };
    EXPECT_THROW(wait(), std::runtime_error);
    // Gone before its time: `then` never runs, nothing is thrown.
    EXPECT_NO_THROW(
        util::Deadline(std::chrono::minutes(1), [] { throw std::runtime_error("never"); }));
}
