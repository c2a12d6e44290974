#pragma once
// SIGTERM/SIGINT -> a graceful shutdown callback, run on a dedicated thread (not in a signal
// handler, so the callback may lock, log and join).

#include <functional>
#include <thread>

namespace cutcalc::service {

class ShutdownSignals {
 public:
  // Blocks SIGTERM and SIGINT in the calling thread and every thread started after it; call first.
  ShutdownSignals();
  ~ShutdownSignals();
  ShutdownSignals(const ShutdownSignals&) = delete;
  ShutdownSignals& operator=(const ShutdownSignals&) = delete;

  // Starts waiting; `on_signal` runs once, with the signal's name.
  void on_shutdown(std::function<void(const char* signal_name)> on_signal);

 private:
  std::thread waiter_;
};

}  // namespace cutcalc::service
