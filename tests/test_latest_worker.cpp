// test_latest_worker.cpp - util::LatestWorker (latest_worker.h) with fake slow jobs, ordered
// by promises rather than by time: a newer job supersedes an older one, queued or running,
// and only the newer result lands; a cancelled job's result never lands; a job's exception
// comes out of take(); the destructor cancels a running job and joins.
#include <gtest/gtest.h>

#include <atomic>
#include <future>
#include <stdexcept>

#include "util/latest_worker.h"

namespace {

using Worker = util::LatestWorker<int>;

// A job as Open CASCADE's would be: it tells it started, then runs until it is told to go on
// (or, with `untilCancelled`, until it sees its flag), and answers `value` whatever it saw,
// as an uninterruptible call would.
struct SlowJob {
    std::shared_ptr<std::promise<void>> started = std::make_shared<std::promise<void>>();
    std::shared_ptr<std::promise<void>> goOn = std::make_shared<std::promise<void>>();
    Worker::Job job(int value, bool untilCancelled = false) const {
        return [started = started, goOn = std::shared_future<void>(goOn->get_future()), value,
                untilCancelled](const std::atomic<bool>& cancelled) -> std::optional<int> {
            started->set_value();
            if (untilCancelled)
                while (!cancelled.load()) std::this_thread::yield();
            else
                goOn.wait();
            return value;
        };
    }
};

TEST(LatestWorker, NewerQueuedJobReplacesTheOlderOneUnrun) {
    std::atomic<int> landed{0}, ran{0};
    Worker worker([&] { ++landed; });
    worker.hold(true);
    auto counted = [&](int value) {
        return [&ran, value](const std::atomic<bool>&) -> std::optional<int> {
            ++ran;
            return value;
        };
    };
    worker.submit(counted(1));
    worker.submit(counted(2));
    EXPECT_TRUE(worker.pending());
    EXPECT_FALSE(worker.landed());
    worker.hold(false);
    worker.wait();
    EXPECT_EQ(worker.take(), 2);
    EXPECT_EQ(ran.load(), 1); // job 1 never started
    EXPECT_EQ(landed.load(), 1);
    EXPECT_FALSE(worker.take()); // once
    EXPECT_FALSE(worker.pending());
}

TEST(LatestWorker, RunningJobSupersededKeepsItsResultToItself) {
    Worker worker;
    SlowJob old, newer;
    worker.submit(old.job(1));
    old.started->get_future().wait(); // job 1 runs
    worker.submit(newer.job(2));
    old.goOn->set_value();              // job 1 ends with its answer, after job 2 was asked
    newer.started->get_future().wait(); // one thread: job 1 has ended
    EXPECT_FALSE(worker.landed());
    EXPECT_FALSE(worker.take());
    EXPECT_TRUE(worker.pending());
    newer.goOn->set_value();
    worker.wait();
    EXPECT_EQ(worker.take(), 2);
    EXPECT_FALSE(worker.take());
}

TEST(LatestWorker, SupersededJobSeesItsCancelFlag) {
    Worker worker;
    SlowJob old;
    worker.submit(old.job(1, true)); // ends only once cancelled
    old.started->get_future().wait();
    worker.submit([](const std::atomic<bool>&) -> std::optional<int> { return 2; });
    worker.wait();
    EXPECT_EQ(worker.take(), 2);
}

TEST(LatestWorker, CancelledJobLandsNothing) {
    std::atomic<int> landed{0};
    Worker worker([&] { ++landed; });
    SlowJob job;
    worker.submit(job.job(1));
    job.started->get_future().wait();
    worker.cancel();
    EXPECT_FALSE(worker.pending());
    job.goOn->set_value();
    // A job after it, to know the first has ended: its result is the only one to land.
    worker.submit([](const std::atomic<bool>&) -> std::optional<int> { return 3; });
    worker.wait();
    EXPECT_EQ(worker.take(), 3);
    EXPECT_EQ(landed.load(), 1);
}

TEST(LatestWorker, JobsExceptionComesOutOfTake) {
    Worker worker;
    worker.submit([](const std::atomic<bool>&) -> std::optional<int> {
        throw std::runtime_error("shape bytes unreadable");
    });
    worker.wait();
    EXPECT_TRUE(worker.landed());
    EXPECT_THROW(worker.take(), std::runtime_error);
    EXPECT_FALSE(worker.landed());
}

TEST(LatestWorker, DestructionCancelsTheRunningJobAndJoins) {
    std::atomic<bool> sawCancel{false};
    auto started = std::make_shared<std::promise<void>>();
    {
        Worker worker;
        worker.submit([&, started](const std::atomic<bool>& cancelled) -> std::optional<int> {
            started->set_value();
            while (!cancelled.load()) std::this_thread::yield();
            sawCancel = true;
            return 1;
        });
        started->get_future().wait();
    } // would hang here without the cancel
    EXPECT_TRUE(sawCancel.load());
}

TEST(LatestWorker, DestructionWhileHeldDropsTheQueuedJob) {
    std::atomic<int> ran{0};
    {
        Worker worker;
        worker.hold(true);
        worker.submit([&](const std::atomic<bool>&) -> std::optional<int> { return ++ran; });
    }
    EXPECT_EQ(ran.load(), 0);
}

} // namespace
