#pragma once
// A gate for tests of concurrent work: what reaches it waits until the test opens it, and the test
// can wait until a number of callers are inside. The waits have a limit only as a safety net
// against a hang; no test measures time.

#include <chrono>
#include <condition_variable>
#include <mutex>

namespace cutcalc::testing {

class Gate {
 public:
  static constexpr auto kPatience = std::chrono::seconds(10);

  // Called by the work: counts itself inside, then waits until open().
  void pass() {
    std::unique_lock lock(mutex_);
    ++inside_;
    changed_.notify_all();
    changed_.wait(lock, [this] { return open_; });
  }
  void open() {
    const std::lock_guard lock(mutex_);
    open_ = true;
    changed_.notify_all();
  }
  // True once `count` callers have reached the gate (false after kPatience).
  bool wait_inside(int count) {
    std::unique_lock lock(mutex_);
    return changed_.wait_for(lock, kPatience, [&] { return inside_ >= count; });
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  int inside_ = 0;
  bool open_ = false;
};

}  // namespace cutcalc::testing
