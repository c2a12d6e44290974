#pragma once
// The listening socket and its accept loop. Binding an address that another socket already
// listens on fails with the reason (EADDRINUSE), so a second cutcalc started on a served port
// exits with a clear message instead of silently sharing the traffic; sharing a port between
// processes (SO_REUSEPORT) happens only when asked for (--reuse-port).

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <string>

#include "service/unique_fd.h"

namespace cutcalc::service {

struct ListenSettings {
  std::string host = "127.0.0.1";  // a name or an address; the first that binds is used
  int port = 8080;                 // 0: a free port
  int backlog = 1024;              // the kernel caps it at net.core.somaxconn
  bool reuse_port = false;         // SO_REUSEPORT: share the port with other processes
};

class Listener {
 public:
  Listener();
  Listener(const Listener&) = delete;
  Listener& operator=(const Listener&) = delete;

  // Binds and listens. Returns the bound port, or -1 with error() saying why.
  int open(const ListenSettings& settings);
  [[nodiscard]] const std::string& error() const { return error_; }

  // Accepts connections and hands each one's descriptor to `adopt` (which takes ownership) until
  // the time stop() set; then closes the listening socket, so new connections are refused. False
  // when it could not run (not open).
  bool run(const std::function<void(int sock)>& adopt);
  // Thread-safe, once: run() goes on accepting for `delay` (the lame duck), then returns.
  void stop(std::chrono::milliseconds delay = {});
  // True once the listening socket is closed (or stop() came before run()).
  [[nodiscard]] bool stopped() const { return closed_.load(); }

 private:
  UniqueFd socket_;
  UniqueFd wake_;  // eventfd: stop() wakes run()
  std::atomic<bool> stop_requested_{false};
  // When run() stops accepting, steady-clock nanoseconds; max: not asked yet.
  std::atomic<std::int64_t> stop_at_ns_{INT64_MAX};
  std::atomic<bool> closed_{false};
  std::string error_;
};

}  // namespace cutcalc::service
