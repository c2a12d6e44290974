#pragma once
// The HTTP service: the listener, the engine, the routes (calculations and operational ones) and
// what every request goes through (request id, 404/405, problem bodies, access log, metrics).

#include <atomic>
#include <chrono>
#include <exception>
#include <memory>
#include <string>
#include <string_view>

#include "service/config.h"
#include "service/cors.h"
#include "service/http_event_loop.h"
#include "service/listener.h"
#include "service/metrics.h"
#include "service/route_table.h"

namespace cutcalc::service {

class HttpApp {
 public:
  explicit HttpApp(Config config);
  ~HttpApp();
  HttpApp(const HttpApp&) = delete;
  HttpApp& operator=(const HttpApp&) = delete;

  // Binds the configured host and port; returns the bound port (useful with port 0) or -1, with
  // bind_error() saying why.
  int bind();
  [[nodiscard]] const std::string& bind_error() const { return listener_.error(); }
  // Serves until shutdown() is called; returns after in-flight requests have been answered.
  bool serve();
  // Thread-safe: /readyz turns 503 and every response says Connection: close at once; the listener
  // accepts for the lame-duck period more, then closes; then idle connections close after a short
  // grace and in-flight requests finish (README.md, "Restarts").
  void shutdown();
  // Serves a connected stream socket as if it had been accepted (takes ownership); for the
  // byte-level fuzzer, which talks to the engine over a socketpair.
  void serve_connection(int sock);
  // Every path served and its Allow value (for tests that must cover every route).
  [[nodiscard]] const RouteTable& routes() const { return routes_; }
  // The engine's counters (what /metrics shows of connections and large bodies).
  [[nodiscard]] const ConnectionCounters& counters() const { return counters_; }

  // One request, as the engine hands it over (also for tests without a socket).
  Reply answer(const HttpRequest& request);

 private:
  struct Exchange;  // one request's bookkeeping, from answer() to its response
  // The response for an error the engine answers by itself (framing, size, connection cap).
  std::string engine_error_response(const EngineError& error);
  // Metrics and access log of a finished request; returns `res`.
  HttpResponse finish(const Exchange& exchange, HttpResponse res);
  // The one answer of a calculation handed to the pool (`res`: its headers so far).
  HttpResponse settle_calculation(const Exchange& exchange, HttpResponse res,
                                  DeferredOutcome outcome, HttpResponse computed,
                                  std::string_view failure);
  // A 500 problem for a handler that threw (a bug): logged, counted, answered.
  HttpResponse internal_error(const Exchange& exchange, std::string_view error);
  void install_routes();

  Config config_;
  Metrics metrics_;
  RouteTable routes_;
  CorsPolicy cors_;
  ConnectionCounters counters_;
  std::atomic<bool> draining_{false};
  Listener listener_;
  std::unique_ptr<EventLoopEngine> engine_;  // last: its threads call into everything above
};

}  // namespace cutcalc::service
