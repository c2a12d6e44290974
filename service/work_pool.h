#pragma once
// The calculation pool: threads that run the heavy calculations (a program of up to megabytes)
// off the event loops, so that the loops keep reading, framing and answering light requests,
// health probes and metrics meanwhile. The queue is bounded: a job that does not fit is refused at
// once (the caller answers 503 with Retry-After) instead of waiting behind work it cannot see.
//
// The workers run at a lower scheduling priority than the loops (a higher nice value): on a busy
// machine the loops, whose requests take microseconds, get the CPU first; the pool takes what is
// left, which is all of it when the loops are idle.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace cutcalc::service {

struct WorkPoolSettings {
  std::size_t threads = 2;
  std::size_t queue_limit = 16;  // jobs waiting for a thread; beyond: refused
  int nice_increment = 5;        // the workers' nice value above the loops'; 0: the same
};

// Monotonic counters and gauges, for metrics.
struct WorkPoolCounters {
  std::atomic<std::uint64_t> jobs{0};               // started
  std::atomic<std::uint64_t> refused{0};            // the queue was full
  std::atomic<std::uint64_t> wait_microseconds{0};  // summed over started jobs: queued to started
  std::atomic<std::uint64_t> queued{0};             // waiting now (gauge)
  std::atomic<std::uint64_t> running{0};            // running now (gauge)
};

class WorkPool {
 public:
  WorkPool(WorkPoolSettings settings, WorkPoolCounters& counters);
  WorkPool(const WorkPool&) = delete;
  WorkPool& operator=(const WorkPool&) = delete;
  // Runs the jobs still queued, then joins the threads.
  ~WorkPool();

  // Queues `job`; false (and `job` not kept) when the queue is full. Thread-safe.
  bool try_submit(std::function<void()> job);

 private:
  using Clock = std::chrono::steady_clock;
  struct Queued {
    std::function<void()> job;
    Clock::time_point since;
  };
  void work();

  const WorkPoolSettings settings_;
  WorkPoolCounters& counters_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<Queued> queue_;  // guarded by mutex_
  bool quit_ = false;         // guarded by mutex_
  std::vector<std::thread> threads_;
};

}  // namespace cutcalc::service
