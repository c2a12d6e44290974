#pragma once
// A bounded, elastic httplib::TaskQueue.
//
// cpp-httplib runs one task per accepted connection, and that task keeps its thread for the whole
// life of the connection (all its keep-alive requests and the idle waits between them). The
// library's own ThreadPool has a fixed number of threads, so once that many keep-alive
// connections are open, every further connection waits in the queue until one of them closes.
//
// This pool keeps `min_threads` threads ready, starts another thread whenever a task arrives and
// no thread is idle, up to `max_threads`, and lets threads beyond `min_threads` exit after
// `idle_timeout` without work. At the cap, tasks wait in a FIFO of at most `max_queued`; when
// that is full, enqueue() blocks the caller (httplib's accept loop), so further connections wait
// in the kernel's listen backlog instead of piling up as open file descriptors in the process.
// Nothing grows without bound.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <list>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include <httplib.h>

namespace cutcalc::service {

// Load figures published by the pool, readable without its lock (e.g. by the connection loop,
// to stop holding idle keep-alive connections when threads run short).
struct PoolLoad {
  std::atomic<std::size_t> live_threads{0};
  std::atomic<std::size_t> busy_threads{0};  // threads running a task
  std::atomic<std::size_t> queued_tasks{0};  // tasks waiting for a thread
  std::atomic<std::size_t> peak_threads{0};
  std::atomic<std::size_t> max_threads{0};
};

class ElasticThreadPool final : public httplib::TaskQueue {
 public:
  struct Limits {
    std::size_t min_threads = 8;
    std::size_t max_threads = 512;
    std::size_t max_queued = 1024;
    std::chrono::milliseconds idle_timeout{30000};
  };

  explicit ElasticThreadPool(Limits limits, std::shared_ptr<PoolLoad> load = nullptr);
  ElasticThreadPool(const ElasticThreadPool&) = delete;
  ElasticThreadPool& operator=(const ElasticThreadPool&) = delete;
  ~ElasticThreadPool() override;

  void enqueue(std::function<void()> fn) override;
  // Like enqueue(), but never waits: false (and `fn` untouched) when the queue is full at the
  // cap or the pool is shut down.
  bool try_enqueue(std::function<void()>& fn);
  // Runs every queued task, then joins every thread. Idempotent.
  void shutdown() override;

  const PoolLoad& load() const { return *load_; }

 private:
  using ThreadList = std::list<std::thread>;

  void worker(ThreadList::iterator self);
  // Queues the task and starts a thread for it if none is idle; may hand the task back to run
  // inline (returned non-empty) when no thread exists or can be started.
  std::function<void()> push_locked(std::function<void()> fn);
  bool spawn_locked();          // false if the thread could not be started
  void reap_finished_locked();  // joins threads that exited for idleness
  void publish_locked();

  const Limits limits_;
  std::shared_ptr<PoolLoad> load_;

  std::mutex mutex_;
  std::condition_variable work_cv_;   // a task arrived, or shutdown
  std::condition_variable space_cv_;  // the queue has room again, or shutdown
  std::deque<std::function<void()>> tasks_;
  ThreadList threads_;
  std::vector<ThreadList::iterator> finished_;  // exited, not yet joined
  std::size_t live_ = 0;
  std::size_t idle_ = 0;
  std::size_t busy_ = 0;
  bool shutdown_ = false;
  bool joined_ = false;
};

}  // namespace cutcalc::service
