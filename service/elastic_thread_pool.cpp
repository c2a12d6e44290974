#include "service/elastic_thread_pool.h"

#include <algorithm>
#include <system_error>
#include <utility>

namespace cutcalc::service {

ElasticThreadPool::ElasticThreadPool(Limits limits, std::shared_ptr<PoolLoad> load)
    : limits_{std::max<std::size_t>(limits.min_threads, 1),
              std::max(limits.max_threads, std::max<std::size_t>(limits.min_threads, 1)),
              std::max<std::size_t>(limits.max_queued, 1), limits.idle_timeout},
      load_(load ? std::move(load) : std::make_shared<PoolLoad>()) {
  const std::lock_guard lock(mutex_);
  load_->max_threads = limits_.max_threads;
  for (std::size_t i = 0; i < limits_.min_threads; ++i) {
    if (!spawn_locked()) break;
  }
  publish_locked();
}

ElasticThreadPool::~ElasticThreadPool() { shutdown(); }

void ElasticThreadPool::enqueue(std::function<void()> fn) {
  std::unique_lock lock(mutex_);
  // Back-pressure: at the cap with a full queue, the caller (the accept loop) waits for room.
  space_cv_.wait(lock, [&] { return shutdown_ || tasks_.size() < limits_.max_queued; });
  if (shutdown_) {
    // httplib never enqueues after shutdown; if it ever did, run the task rather than leak it.
    lock.unlock();
    fn();
    return;
  }
  auto inline_task = push_locked(std::move(fn));
  lock.unlock();
  if (inline_task) {
    inline_task();
  } else {
    work_cv_.notify_one();
  }
}

bool ElasticThreadPool::try_enqueue(std::function<void()>& fn) {
  std::unique_lock lock(mutex_);
  if (shutdown_ || tasks_.size() >= limits_.max_queued) return false;
  auto inline_task = push_locked(std::move(fn));
  lock.unlock();
  if (inline_task) {
    inline_task();
  } else {
    work_cv_.notify_one();
  }
  return true;
}

std::function<void()> ElasticThreadPool::push_locked(std::function<void()> fn) {
  reap_finished_locked();
  tasks_.push_back(std::move(fn));
  if (idle_ < tasks_.size() && live_ < limits_.max_threads && !spawn_locked() && live_ == 0) {
    // No thread at all and none can be started: the caller runs it, so nothing is leaked.
    auto task = std::move(tasks_.back());
    tasks_.pop_back();
    publish_locked();
    return task;
  }
  publish_locked();
  return {};
}

void ElasticThreadPool::shutdown() {
  {
    const std::lock_guard lock(mutex_);
    if (joined_) return;
    shutdown_ = true;
  }
  work_cv_.notify_all();
  space_cv_.notify_all();
  // threads_ is only changed by enqueue() and shutdown(), which httplib calls from one thread;
  // workers only touch finished_, so the list can be walked without the lock.
  for (auto& thread : threads_) {
    if (thread.joinable()) thread.join();
  }
  std::deque<std::function<void()>> leftover;
  {
    const std::lock_guard lock(mutex_);
    threads_.clear();
    finished_.clear();
    leftover.swap(tasks_);  // only if no thread could ever be started
    joined_ = true;
    publish_locked();
  }
  for (auto& task : leftover) task();
}

void ElasticThreadPool::worker(ThreadList::iterator self) {
  std::unique_lock lock(mutex_);
  for (;;) {
    while (tasks_.empty() && !shutdown_) {
      reap_finished_locked();  // free the stacks of threads that exited for idleness
      ++idle_;
      const bool woken = work_cv_.wait_for(lock, limits_.idle_timeout,
                                           [&] { return shutdown_ || !tasks_.empty(); });
      --idle_;
      if (!woken && live_ > limits_.min_threads) {
        --live_;
        finished_.push_back(self);
        publish_locked();
        return;
      }
    }
    if (tasks_.empty()) {  // shutdown with nothing left to run
      --live_;
      publish_locked();
      return;
    }
    auto task = std::move(tasks_.front());
    tasks_.pop_front();
    ++busy_;
    publish_locked();
    lock.unlock();
    space_cv_.notify_one();
    try {
      task();
    } catch (...) {
      // httplib's connection task catches handler exceptions itself; nothing may escape a
      // worker thread, so anything else is dropped here.
    }
    task = nullptr;  // destroy the closure outside the lock
    lock.lock();
    --busy_;
    publish_locked();
  }
}

bool ElasticThreadPool::spawn_locked() {
  if (shutdown_ || live_ >= limits_.max_threads) return false;
  threads_.emplace_back();
  const auto self = std::prev(threads_.end());
  try {
    // The new thread blocks on mutex_ (held here) until this assignment is complete.
    *self = std::thread([this, self] { worker(self); });
  } catch (const std::system_error&) {
    threads_.erase(self);
    return false;
  }
  ++live_;
  load_->peak_threads = std::max(load_->peak_threads.load(), live_);
  return true;
}

void ElasticThreadPool::reap_finished_locked() {
  // After shutdown_ is set, shutdown() walks threads_ without the lock: leave the list alone.
  if (shutdown_) return;
  for (const auto it : finished_) {
    // The thread has left worker() (it pushed itself here as its last act under the lock), so
    // this join returns at once.
    if (it->joinable()) it->join();
    threads_.erase(it);
  }
  finished_.clear();
}

void ElasticThreadPool::publish_locked() {
  load_->live_threads = live_;
  load_->busy_threads = busy_;
  load_->queued_tasks = tasks_.size();
}

}  // namespace cutcalc::service
