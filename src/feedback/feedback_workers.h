// FeedbackWorkers: the threads the feedback stage runs on while Bullet steps. One job at a time; inside it the
// work may be split over every thread with parallel_for. Deterministic by construction: chunks write disjoint
// outputs and reductions happen after the join.
//
// Waiting spins before it sleeps (up to kSpin): on the 2-vCPU VMs this runs on, a sleeping thread's vCPU is halted
// and waking it took from tens of microseconds to milliseconds, so a worker that slept between evaluations often
// started so late that the simulation thread then waited for it — the parallel mode's critical-path cost was no
// lower than evaluating on the simulation thread. Jobs come every few steps (milliseconds), so a short spin keeps
// the worker awake between them at the price of one busy core while a TC-SB body runs.
//
// A job the worker has not begun when wait() is called is taken back and run by the waiting thread. On a shared VM
// the worker's vCPU is now and then away for milliseconds; the simulation thread, which would otherwise spin idle
// until it returns, does the job itself (measured on the Intel VM: compressed TC-SB repetitions whose mean step was
// 1.3-5x their median, the excess in the feedback stage's wait; docs/investigations/reproduction-verdicts.md). The
// job is the same function of the same inputs whichever thread runs it, so results do not depend on who did.
//
// A job (or a parallel_for chunk) that throws does not end its thread: the exception is kept and rethrown by the
// wait() that joins the job (by parallel_for for a chunk), on the thread that waits — never std::terminate, and never
// a waiter left waiting for a job that will not finish.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace tcsb {

/// A tiny fixed pool: thread 0 runs posted jobs, the others only help with parallel_for chunks.
class FeedbackWorkers {
 public:
  explicit FeedbackWorkers(int threads);
  ~FeedbackWorkers();
  FeedbackWorkers(const FeedbackWorkers&) = delete;
  FeedbackWorkers& operator=(const FeedbackWorkers&) = delete;

  /// Hands a job to thread 0. At most one job is pending: call wait() before posting the next.
  void post(std::function<void()> job);
  /// Returns once the posted job (if any) has finished: runs it on the calling thread if thread 0 has not begun it,
  /// else waits for thread 0. Rethrows what the job threw, wherever it ran.
  void wait();
  /// No job will come for a while: thread 0 stops spinning and sleeps until the next post().
  void park() { parked_.store(true, std::memory_order_release); }
  /// Jobs will come again: wakes thread 0 (an empty job, waited for) so that it spins for the next one instead of
  /// waking late from its sleep inside a timed step.
  void wake();
  /// From inside a job: runs fn(chunk) for every chunk in [0, chunks) over all threads; returns when all are done,
  /// then rethrows the first exception a chunk threw (every chunk still ran or threw).
  void parallel_for(int chunks, const std::function<void(int)>& fn);
  int threads() const { return static_cast<int>(helpers_.size()) + 1; }
  /// How many posted jobs wait() ran on the calling thread because thread 0 had not begun them.
  long taken_back() const { return taken_back_.load(std::memory_order_relaxed); }

 private:
  void coordinator_loop();
  void helper_loop();
  /// Tells every started thread to stop and joins it (the destructor, and a constructor that failed half-way).
  void stop_and_join();
  void run_chunks();
  /// Returns once the pending job has finished, without taking it back.
  void wait_for_worker();
  /// Runs the job, and keeps what it throws in failure_ (the caller does not hold mutex_); then marks it finished.
  void run_job(const std::function<void()>& job);
  /// Rethrows, once, what the last finished job threw.
  void rethrow_failure();
  /// Takes the posted job that nobody has begun (empty if there is none); the caller holds mutex_.
  std::function<void()> take_job();
  /// Marks the pending job finished and wakes its waiter; the caller holds mutex_.
  void finish_job();
  /// Spins (pausing the core) until `ready()` or kSpin has passed; returns ready().
  template <class Ready>
  static bool spin_until(Ready ready);
  static constexpr std::chrono::milliseconds kSpin{20};

  std::mutex mutex_;
  std::condition_variable wake_, done_;
  std::function<void()> job_;                // posted and not yet begun by anyone
  bool job_pending_ = false, stop_ = false;  // posted and not yet finished
  // Lock-free mirrors for spinning: of job_pending_, of a non-empty job_, and of stop_.
  std::atomic<bool> pending_{false}, available_{false}, stopping_{false};
  std::atomic<bool> parked_{false};  // park() was called since the last post()
  std::atomic<long> taken_back_{0};
  std::exception_ptr failure_;        // what the last job threw, until wait() rethrows it; under mutex_
  std::atomic<bool> failed_{false};   // failure_ is set (lock-free for the common case: no failure)
  std::exception_ptr chunk_failure_;  // the first exception of the current parallel_for's chunks; under mutex_
  // parallel_for state
  const std::function<void(int)>* chunk_fn_ = nullptr;
  std::atomic<int> chunk_count_{0};
  // Parked far beyond any chunk count between calls, so a helper waking late takes no chunk of a finished call.
  static constexpr int kParked = 1 << 30;
  std::atomic<int> next_chunk_{kParked};
  int chunks_done_ = 0;
  long generation_ = 0;
  std::thread coordinator_;
  std::vector<std::thread> helpers_;
};

}  // namespace tcsb
