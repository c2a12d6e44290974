#pragma once
// A gate for tests of concurrent work: what reaches it waits until the test opens it, and the test
// can wait until a number of callers are inside. The waits have a limit only as a safety net
// against a hang; no test measures time.

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

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

// Polls `condition` until it holds (true) or Gate::kPatience passes (false): a safety net against
// a hang, not a measurement.
inline bool eventually(const std::function<bool()>& condition) {
  const auto until = std::chrono::steady_clock::now() + Gate::kPatience;
  while (!condition()) {
    if (std::chrono::steady_clock::now() >= until) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return true;
}

}  // namespace cutcalc::testing
