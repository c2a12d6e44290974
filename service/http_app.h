#pragma once
// The HTTP service: the tuned server, the calculation and operational routes, and the middleware
// every request goes through (request id, 404/405, problem bodies, access log, metrics).

#include <atomic>
#include <memory>

#include "service/config.h"
#include "service/cors.h"
#include "service/http_tuning.h"
#include "service/metrics.h"
#include "service/route_table.h"

namespace cutcalc::service {

class HttpApp {
 public:
  explicit HttpApp(Config config);
  ~HttpApp();
  HttpApp(const HttpApp&) = delete;
  HttpApp& operator=(const HttpApp&) = delete;

  // Binds the configured host and port; returns the bound port (useful with port 0) or -1.
  int bind();
  // Serves until shutdown() is called; returns after in-flight requests have been answered.
  bool serve();
  // Thread-safe: readiness turns 503, the listener closes, in-flight requests finish.
  void shutdown();
  // Serves a connected stream socket as if it had been accepted (takes ownership); for the
  // byte-level fuzzer, which talks to the engine over a socketpair.
  void serve_connection(int sock);
  // Every path served and its Allow value (for tests that must cover every route).
  [[nodiscard]] const RouteTable& routes() const { return routes_; }

 private:
  // The response for an error the engine answers by itself (framing, size, connection cap).
  std::string engine_error_response(const EngineError& error);
  void install_middleware();
  void install_routes();

  Config config_;
  Metrics metrics_;
  std::unique_ptr<TunedServer> server_;
  RouteTable routes_;
  CorsPolicy cors_;
  std::atomic<bool> draining_{false};
};

}  // namespace cutcalc::service
