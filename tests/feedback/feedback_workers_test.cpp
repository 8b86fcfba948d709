// FeedbackWorkers: jobs run on the worker and wait() returns only after they finished, whether the worker was
// spinning for the job or sleeping (parked, or spun out); parallel_for covers every chunk once.
#include "feedback/feedback_workers.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

namespace tcsb {
namespace {

/// Posts a job that records its thread and sleeps briefly, waits, and checks it ran to the end off this thread.
void post_and_check(FeedbackWorkers& workers) {
  std::atomic<bool> done{false};
  std::thread::id ran_on;
  workers.post([&] {
    ran_on = std::this_thread::get_id();
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    done = true;
  });
  workers.wait();
  EXPECT_TRUE(done.load());
  EXPECT_NE(ran_on, std::this_thread::get_id());
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

}  // namespace
}  // namespace tcsb
