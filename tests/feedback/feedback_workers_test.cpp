// FeedbackWorkers: every posted job runs exactly once and wait() returns only after it finished, whether the worker
// was spinning for the job or sleeping (parked, or spun out), or wait() took it back; parallel_for covers every
// chunk once.
#include "feedback/feedback_workers.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

namespace tcsb {
namespace {

/// Posts a job that counts its runs and sleeps briefly, waits, and checks it ran once and to the end. Returns whether
/// it ran on this thread (wait() took it back).
bool post_and_check(FeedbackWorkers& workers) {
  std::atomic<int> runs{0};
  std::atomic<bool> done{false};
  std::thread::id ran_on;
  workers.post([&] {
    ++runs;
    ran_on = std::this_thread::get_id();
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    done = true;
  });
  workers.wait();
  EXPECT_TRUE(done.load());
  EXPECT_EQ(runs.load(), 1);
  return ran_on == std::this_thread::get_id();
}

TEST(FeedbackWorkers, WaitReturnsAfterTheJobFinished) {
  FeedbackWorkers workers(1);
  for (int i = 0; i < 20; ++i) post_and_check(workers);  // back to back: the worker is still spinning
}

TEST(FeedbackWorkers, AParkedWorkerStillRunsTheNextJob) {
  FeedbackWorkers workers(1);
  post_and_check(workers);
  workers.park();
  std::this_thread::sleep_for(std::chrono::milliseconds(5));  // it is asleep now
  post_and_check(workers);
}

TEST(FeedbackWorkers, AWokenWorkerRunsTheNextJob) {
  FeedbackWorkers workers(1);
  post_and_check(workers);
  workers.park();
  std::this_thread::sleep_for(std::chrono::milliseconds(5));
  workers.wake();  // returns once the worker ran the empty job: it is awake
  post_and_check(workers);
  workers.wake();  // also while it is still spinning
  post_and_check(workers);
}

TEST(FeedbackWorkers, AWorkerThatSpunOutWakesForTheNextJob) {
  FeedbackWorkers workers(1);
  post_and_check(workers);
  std::this_thread::sleep_for(std::chrono::milliseconds(40));  // longer than the spin: it sleeps on the condition
  post_and_check(workers);
}

TEST(FeedbackWorkers, WaitTakesBackAJobTheWorkerHasNotBegun) {
  // A worker asleep (parked) needs far longer to wake than wait() needs to take the lock, so wait() runs the job;
  // one in fifty is enough to show the path works (a wake-up winning the race every time would be a scheduler
  // that runs a woken thread before the one that woke it returns from notify).
  FeedbackWorkers workers(1);
  int taken = 0;
  for (int i = 0; i < 50; ++i) {
    workers.park();
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    if (post_and_check(workers)) ++taken;
  }
  EXPECT_GT(taken, 0);
  EXPECT_EQ(workers.taken_back(), taken);
}

TEST(FeedbackWorkers, EveryJobRunsOnceWhoeverRunsIt) {
  // Back to back with no gap, the worker and wait() race for every job: neither may run one twice or lose one.
  FeedbackWorkers workers(1);
  std::atomic<int> runs{0};
  constexpr int kJobs = 20000;
  for (int i = 0; i < kJobs; ++i) {
    workers.post([&] { ++runs; });
    workers.wait();
    ASSERT_EQ(runs.load(), i + 1);
  }
  // A wake() after a take-back still reaches the worker (it runs wake's empty job itself).
  workers.park();
  workers.wake();
  post_and_check(workers);
}

TEST(FeedbackWorkers, WaitWithoutAJobReturnsAtOnce) {
  FeedbackWorkers workers(1);
  workers.wait();
  workers.park();
  workers.wait();
  SUCCEED();
}

TEST(FeedbackWorkers, ParallelForRunsEveryChunkOnce) {
  for (int threads : {1, 2, 3}) {
    FeedbackWorkers workers(threads);
    std::vector<std::atomic<int>> hits(64);
    workers.post([&] { workers.parallel_for(64, [&](int c) { ++hits[static_cast<std::size_t>(c)]; }); });
    workers.wait();
    for (std::size_t c = 0; c < hits.size(); ++c)
      EXPECT_EQ(hits[c].load(), 1) << "threads " << threads << " chunk " << c;
  }
}

TEST(FeedbackWorkers, AJobThatThrowsOnTheWorkerIsRethrownByWaitAndTheWorkerLivesOn) {
  // Without the rethrow, the worker thread ended with the exception (std::terminate), or a waiter waited forever.
  FeedbackWorkers workers(1);
  std::atomic<bool> begun{false};
  std::thread::id ran_on;
  workers.post([&] {
    ran_on = std::this_thread::get_id();
    begun = true;
    throw std::invalid_argument("camera: up lies along the viewing direction");
  });
  while (!begun.load()) std::this_thread::yield();  // the worker took it: wait() cannot take it back
  EXPECT_THROW(workers.wait(), std::invalid_argument);
  EXPECT_NE(ran_on, std::this_thread::get_id());
  workers.wait();  // rethrown once: nothing pending now
  post_and_check(workers);
}

TEST(FeedbackWorkers, AJobThatThrowsWhenTakenBackIsRethrownByWait) {
  FeedbackWorkers workers(1);
  int thrown = 0;
  for (int i = 0; i < 200; ++i) {  // the worker or wait() may run it: either way wait() throws, and only once
    if (i % 2 == 0) workers.park();
    workers.post([] { throw std::runtime_error("job failed"); });
    try {
      workers.wait();
    } catch (const std::runtime_error&) {
      ++thrown;
    }
    workers.wait();
  }
  EXPECT_EQ(thrown, 200);
  post_and_check(workers);
}

TEST(FeedbackWorkers, AChunkThatThrowsIsRethrownAfterEveryChunkRan) {
  for (int threads : {1, 2, 3}) {
    FeedbackWorkers workers(threads);
    std::vector<std::atomic<int>> hits(64);
    bool rethrown = false;
    workers.post([&] {
      try {
        workers.parallel_for(64, [&](int c) {
          ++hits[static_cast<std::size_t>(c)];
          if (c % 7 == 3) throw std::runtime_error("chunk failed");
        });
      } catch (const std::runtime_error&) {
        rethrown = true;
      }
    });
    workers.wait();
    EXPECT_TRUE(rethrown) << threads << " threads";
    for (std::size_t c = 0; c < hits.size(); ++c) EXPECT_EQ(hits[c].load(), 1) << "threads " << threads;
    // And a chunk's exception reaches wait() when the job lets it through.
    workers.post([&] {
      workers.parallel_for(8, [](int c) {
        if (c == 5) throw std::runtime_error("chunk");
      });
    });
    EXPECT_THROW(workers.wait(), std::runtime_error) << threads << " threads";
    post_and_check(workers);
  }
}

}  // namespace
}  // namespace tcsb
