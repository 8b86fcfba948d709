// FeedbackWorkers: the threads the feedback stage runs on while Bullet steps. One job at a time; inside it the
// work may be split over every thread with parallel_for. Deterministic by construction: chunks write disjoint
// outputs and reductions happen after the join.
//
// Waiting spins before it sleeps (up to kSpin): on the 2-vCPU VMs this runs on, a sleeping thread's vCPU is halted
// and waking it took from tens of microseconds to milliseconds, so a worker that slept between evaluations often
// started so late that the simulation thread then waited for it — the parallel mode's critical-path cost was no
// lower than evaluating on the simulation thread. Jobs come every few steps (milliseconds), so a short spin keeps
// the worker awake between them at the price of one busy core while a TC-SB body runs.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
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
  /// Blocks until the posted job (if any) has finished.
  void wait();
  /// No job will come for a while: thread 0 stops spinning and sleeps until the next post().
  void park() { parked_.store(true, std::memory_order_release); }
  /// Jobs will come again: wakes thread 0 (an empty job, waited for) so that it spins for the next one instead of
  /// waking late from its sleep inside a timed step.
  void wake();
  /// From inside a job: runs fn(chunk) for every chunk in [0, chunks) over all threads; returns when all are done.
  void parallel_for(int chunks, const std::function<void(int)>& fn);
  int threads() const { return static_cast<int>(helpers_.size()) + 1; }

 private:
  void coordinator_loop();
  void helper_loop();
  /// Tells every started thread to stop and joins it (the destructor, and a constructor that failed half-way).
  void stop_and_join();
  void run_chunks();
  /// Spins (pausing the core) until `ready()` or kSpin has passed; returns ready().
  template <class Ready>
  static bool spin_until(Ready ready);
  static constexpr std::chrono::milliseconds kSpin{20};

  std::mutex mutex_;
  std::condition_variable wake_, done_;
  std::function<void()> job_;
  bool job_pending_ = false, stop_ = false;
  std::atomic<bool> pending_{false}, stopping_{false};  // lock-free mirrors of job_pending_ and stop_, for spinning
  std::atomic<bool> parked_{false};                     // park() was called since the last post()
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
