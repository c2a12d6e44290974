#pragma once
// The HTTP engine: epoll loops that own the connections, frame and parse each request strictly,
// once (service/http_framing.h), hand it to the app as a value (service/http_request.h) and write
// the app's response (service/http_response.h). No request ever blocks a loop: a request is served
// only once all of it has arrived, a response the socket cannot take at once waits for EPOLLOUT,
// and a calculation that can be heavy runs on the calculation pool (service/work_pool.h) while the
// loop goes on serving other connections. Idle keep-alive connections and slow clients cost a few
// KiB and no thread.
//
// Ownership (the invariant the code keeps; Boost.Beast's async server is the model):
//  - A connection is one `Connection`, held by exactly one `std::unique_ptr` at any moment: in
//    adopt() (accept thread), then in one loop's inbox (under the inbox mutex), then in that loop's
//    table. It never leaves its loop and is never shared; only its loop's thread touches it.
//  - epoll knows a connection by its file descriptor (`data.fd`), never by a pointer; the loop
//    looks the descriptor up in its table, so an event for a connection that is gone finds nothing.
//  - Work on the pool owns copies of what it reads and never sees the connection: its response
//    comes back to the loop's inbox addressed by descriptor and connection id, and the loop drops
//    it if that connection has closed meanwhile (a reused descriptor has another id).
//  - While a connection waits for the pool it serves nothing more, so pipelined requests are
//    answered in order.
//  - The loop registers the descriptor with epoll after the connection is in its table, and removes
//    it (EPOLL_CTL_DEL, checked) before the connection leaves the table; only then is it destroyed,
//    and its `UniqueFd` closes the descriptor.
//  - New connections are taken from the inbox after a batch of events is handled, so a descriptor
//    number reused by the kernel can never meet a stale event of the same batch.

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "service/engine_counters.h"
#include "service/http_fault.h"
#include "service/http_framing.h"
#include "service/http_limits.h"
#include "service/http_request.h"
#include "service/http_response.h"
#include "service/memory_budget.h"
#include "service/socket_addresses.h"
#include "service/work_pool.h"

namespace cutcalc::service {

struct EventLoopSettings {
  std::size_t loops = 2;
  std::size_t keep_alive_max_requests = 10000;
  std::size_t max_connections = 10000;  // beyond: 503 and close
  HttpLimits limits;                    // framing and timers
  // The memory budget of the requests' work (service/memory_budget.h); the default: none.
  std::uint64_t memory_budget_bytes = UINT64_MAX;
  WorkPoolSettings pool;  // the calculation pool
  bool tcp_nodelay = true;
};

// A large body is held about twice while it is worked on: the calculation's copy until it is
// parsed beside the parsed text, then the parsed text beside what is computed from it (a 32 MiB
// program to time peaked at 65 MiB above the idle process). It is charged so to the memory budget
// from its head on.
inline constexpr std::size_t kLargeBodyHeldTimes = 2;

// A response the engine gives by itself, before any handler (service/http_fault.h): a framing
// error (400), a body over the limit (413), the connection cap or a passing refusal (503). The
// connection closes after it. The views are of the request as far as it was read (empty where it
// was not), so that the answer can carry CORS headers and speak the client's language.
struct EngineError {
  HttpFault fault = HttpFault::malformed_request_line;
  std::string_view method;  // empty when the request line was not read
  std::string_view target;
  std::string_view origin;           // the request's Origin field
  std::string_view accept_language;  // the request's Accept-Language field
  int retry_after_s = 0;             // a 503 for a passing condition (Retry-After); 0: none
};

// How a request handed to the calculation pool ended.
enum class DeferredOutcome {
  computed,     // `run` returned its response
  failed,       // `run` threw (a bug): answered 500
  pool_full,    // the pool's queue was full: never run, 503 with Retry-After
  over_budget,  // the memory budget was spent (answers waiting), before the run or by its
                // answer: 503 with Retry-After
  timed_out,    // HttpLimits::calculation_timeout passed first: stopped, 503 with Retry-After
  abandoned     // the connection closed first (the client went away): stopped, nothing is sent
};

// Work the app hands to the calculation pool instead of answering on the loop. Every request
// handed over is settled exactly once, whatever happens: that is where its metrics and its log
// line are written.
struct DeferredResponse {
  // Runs on a pool thread, given the request as the engine's own copy (the views the app was
  // given die with the call that gave them). `stop` is set once nobody waits for the answer any
  // more (a timeout, a client gone): the calculation should stop at its next check
  // (domain/common/interruption.h). May throw.
  std::function<HttpResponse(OwnedRequest& request, const std::atomic<bool>& stop)> run;
  // Runs on the loop, once: the response that goes out. `computed` is run's response (computed),
  // `failure` what run threw (failed); both empty otherwise. abandoned: the answer is dropped.
  std::function<HttpResponse(DeferredOutcome outcome, HttpResponse computed,
                             std::string_view failure)>
      settle;
};

// The app's answer to one request: a response now, or work for the pool.
using Reply = std::variant<HttpResponse, DeferredResponse>;

class EventLoopEngine {
 public:
  // Answers one request; runs on a loop thread and must not throw.
  using Serve = std::function<Reply(const HttpRequest& request)>;
  // The whole response (status line to body) for an engine error; it must say Connection: close.
  // Called on a loop thread or the accept thread.
  using RenderError = std::function<std::string(const EngineError& error)>;
  // Where the server is in its life; called on the loop threads, once per request framed
  // (HttpRequest::phase) and by the loops' own timers.
  using PhaseOf = std::function<ServerPhase()>;

  EventLoopEngine(EventLoopSettings settings, Serve serve, RenderError render_error, PhaseOf phase,
                  ConnectionCounters& counters);
  EventLoopEngine(const EventLoopEngine&) = delete;
  EventLoopEngine& operator=(const EventLoopEngine&) = delete;
  // Closes every connection (stopping the calculations in flight) and joins the loops, then lets
  // the pool finish its jobs. drain() first answers what is in flight.
  ~EventLoopEngine();

  // Takes ownership of a connected socket (TCP, or any stream socket). Never blocks.
  void adopt(int sock);

  // After the server stopped accepting: waits until every request in flight has been answered
  // (idle connections are closed at once), or until `limit` passes. True when drained.
  bool drain(std::chrono::milliseconds limit) const;

  [[nodiscard]] std::size_t open_connections() const { return open_connections_.load(); }
  [[nodiscard]] const MemoryBudget& memory_budget() const { return budget_; }

 private:
  struct Connection;
  struct Completion;
  struct Piece;
  class Loop;

  const EventLoopSettings settings_;
  const Serve serve_;
  const RenderError render_error_;
  const PhaseOf phase_;
  ConnectionCounters& counters_;
  std::atomic<std::size_t> open_connections_{0};  // adopted and not yet closed
  std::atomic<std::size_t> next_loop_{0};
  std::atomic<std::uint64_t> next_connection_id_{1};
  MemoryBudget budget_;                       // charged by the connections: outlives them
  std::vector<std::unique_ptr<Loop>> loops_;  // their threads use everything above
  std::unique_ptr<WorkPool> pool_;            // its jobs post to the loops (see the destructor)
};

}  // namespace cutcalc::service
