#include "service/work_pool.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>

namespace cutcalc::service {

WorkPool::WorkPool(WorkPoolSettings settings, WorkPoolCounters& counters)
    : settings_(settings), counters_(counters) {
  const std::size_t threads = std::max<std::size_t>(settings_.threads, 1);
  threads_.reserve(threads);
  for (std::size_t i = 0; i < threads; ++i) threads_.emplace_back([this] { work(); });
}

WorkPool::~WorkPool() {
  {
    const std::lock_guard lock(mutex_);
    quit_ = true;
  }
  wake_.notify_all();
  for (std::thread& thread : threads_) thread.join();
}

bool WorkPool::try_submit(std::function<void()> job) {
  {
    const std::lock_guard lock(mutex_);
    if (quit_ || queue_.size() >= settings_.queue_limit) {
      counters_.refused.fetch_add(1, std::memory_order_relaxed);
      return false;
    }
    queue_.push_back({std::move(job), Clock::now()});
    counters_.queued.fetch_add(1, std::memory_order_relaxed);
  }
  wake_.notify_one();
  return true;
}

void WorkPool::work() {
  if (settings_.nice_increment > 0) {
    // Linux: a nice value per thread (setpriority on the thread id). Raising it needs no privilege;
    // if it fails the pool still works, only without the priority.
    const auto tid = static_cast<id_t>(::syscall(SYS_gettid));
    errno = 0;
    const int current = ::getpriority(PRIO_PROCESS, tid);
    if (errno == 0)
      ::setpriority(PRIO_PROCESS, tid, std::min(current + settings_.nice_increment, 19));
  }
  for (;;) {
    Queued next;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [this] { return quit_ || !queue_.empty(); });
      if (queue_.empty()) return;  // quit, and nothing left to run
      next = std::move(queue_.front());
      queue_.pop_front();
      counters_.queued.fetch_sub(1, std::memory_order_relaxed);
    }
    const auto waited =
        std::chrono::duration_cast<std::chrono::microseconds>(Clock::now() - next.since);
    counters_.wait_microseconds.fetch_add(static_cast<std::uint64_t>(waited.count()),
                                          std::memory_order_relaxed);
    counters_.jobs.fetch_add(1, std::memory_order_relaxed);
    counters_.running.fetch_add(1, std::memory_order_relaxed);
    try {
      next.job();
    } catch (...) {  // a job reports its own errors; nothing may end a worker
    }
    counters_.running.fetch_sub(1, std::memory_order_relaxed);
  }
}

}  // namespace cutcalc::service
