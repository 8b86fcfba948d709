#include "feedback/feedback_workers.h"

#include <utility>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace tcsb {

template <class Ready>
bool FeedbackWorkers::spin_until(Ready ready) {
  const auto until = std::chrono::steady_clock::now() + kSpin;
  for (int i = 0; !ready(); ++i) {
#if defined(__x86_64__) || defined(__i386__)
    _mm_pause();
#else
    std::this_thread::yield();
#endif
    if ((i & 255) == 255 && std::chrono::steady_clock::now() > until) return ready();
  }
  return true;
}

FeedbackWorkers::FeedbackWorkers(int threads) {
  try {
    coordinator_ = std::thread([this] { coordinator_loop(); });
    for (int i = 1; i < threads; ++i) helpers_.emplace_back([this] { helper_loop(); });
  } catch (...) {
    // A thread that could not start (std::system_error, EAGAIN: a memory or process limit) must not leave the
    // started ones joinable: their destructors would std::terminate the process instead of reporting the error.
    stop_and_join();
    throw;
  }
}

FeedbackWorkers::~FeedbackWorkers() { stop_and_join(); }

void FeedbackWorkers::stop_and_join() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
    stopping_.store(true, std::memory_order_release);
  }
  wake_.notify_all();
  if (coordinator_.joinable()) coordinator_.join();
  for (std::thread& t : helpers_) t.join();
}

void FeedbackWorkers::post(std::function<void()> job) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    job_ = std::move(job);
    job_pending_ = true;
    parked_.store(false, std::memory_order_release);
    pending_.store(true, std::memory_order_release);
    available_.store(true, std::memory_order_release);
  }
  wake_.notify_all();
}

std::function<void()> FeedbackWorkers::take_job() {
  std::function<void()> job = std::move(job_);
  job_ = nullptr;
  available_.store(false, std::memory_order_release);
  return job;
}

void FeedbackWorkers::finish_job() {
  job_pending_ = false;
  pending_.store(false, std::memory_order_release);
  done_.notify_all();
}

void FeedbackWorkers::run_job(const std::function<void()>& job) {
  std::exception_ptr failure;
  try {
    job();
  } catch (...) {
    failure = std::current_exception();
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (failure) {
    failure_ = failure;
    failed_.store(true, std::memory_order_release);
  }
  finish_job();
}

void FeedbackWorkers::rethrow_failure() {
  if (!failed_.load(std::memory_order_acquire)) return;
  std::exception_ptr failure;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    failure = std::exchange(failure_, nullptr);
    failed_.store(false, std::memory_order_release);
  }
  if (failure) std::rethrow_exception(failure);
}

void FeedbackWorkers::wait() {
  std::unique_lock<std::mutex> lock(mutex_);
  if (std::function<void()> job = take_job()) {
    taken_back_.fetch_add(1, std::memory_order_relaxed);
    lock.unlock();
    run_job(job);
  } else {
    lock.unlock();
    wait_for_worker();
  }
  rethrow_failure();
}

void FeedbackWorkers::wait_for_worker() {
  if (spin_until([this] { return !pending_.load(std::memory_order_acquire); })) return;
  std::unique_lock<std::mutex> lock(mutex_);
  done_.wait(lock, [this] { return !job_pending_; });
}

void FeedbackWorkers::wake() {
  post([] {});
  wait_for_worker();  // not wait(): the point is that thread 0 runs it and so is awake
}

void FeedbackWorkers::coordinator_loop() {
  for (;;) {
    const bool ready = spin_until([this] {
      return stopping_.load(std::memory_order_acquire) || available_.load(std::memory_order_acquire) ||
             parked_.load(std::memory_order_acquire);
    });
    std::unique_lock<std::mutex> lock(mutex_);
    if (!stop_ && !job_) {
      // A job seen while spinning but taken back by wait() before this thread got the lock: spin for the next one.
      if (ready && !parked_.load(std::memory_order_acquire)) continue;
      wake_.wait(lock, [this] { return stop_ || job_; });
    }
    if (stop_) return;
    std::function<void()> job = take_job();
    lock.unlock();
    run_job(job);  // an exception is kept for the waiter: this thread lives on
  }
}

void FeedbackWorkers::run_chunks() {
  for (int c = next_chunk_.fetch_add(1); c < chunk_count_; c = next_chunk_.fetch_add(1)) {
    std::exception_ptr failure;
    try {
      (*chunk_fn_)(c);
    } catch (...) {
      failure = std::current_exception();  // a chunk that threw is done too, or parallel_for would wait forever
    }
    std::lock_guard<std::mutex> lock(mutex_);
    if (failure && !chunk_failure_) chunk_failure_ = failure;
    if (++chunks_done_ == chunk_count_) done_.notify_all();
  }
}

void FeedbackWorkers::helper_loop() {
  long seen = 0;
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
    if (stop_) return;
    seen = generation_;
    lock.unlock();
    run_chunks();
    lock.lock();
  }
}

void FeedbackWorkers::parallel_for(int chunks, const std::function<void(int)>& fn) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    chunk_fn_ = &fn;
    chunk_count_ = chunks;
    chunks_done_ = 0;
    next_chunk_.store(0);  // last: opens the chunks
    ++generation_;
  }
  wake_.notify_all();
  run_chunks();
  std::unique_lock<std::mutex> lock(mutex_);
  done_.wait(lock, [&] { return chunks_done_ == chunk_count_; });
  next_chunk_.store(kParked);
  chunk_fn_ = nullptr;
  if (std::exception_ptr failure = std::exchange(chunk_failure_, nullptr)) {
    lock.unlock();
    std::rethrow_exception(failure);
  }
}

}  // namespace tcsb
