#pragma once
// The HTTP engine: epoll loops that own the connections, frame each request strictly
// (service/http_framing.h) and hand a complete one to the HTTP library to parse, route and answer
// (service/http_connection.h: memory in, memory out). No request ever blocks a thread: a request
// is served only once all of it has arrived, and a response the socket cannot take at once waits
// for EPOLLOUT. Idle keep-alive connections and slow clients cost a few KiB and no thread.
//
// Ownership (the invariant the code keeps; Boost.Beast's async server is the model):
//  - A connection is one `Connection`, held by exactly one `std::unique_ptr` at any moment: in
//    adopt() (accept thread), then in one loop's inbox (under the inbox mutex), then in that loop's
//    table. It never leaves its loop and is never shared; only its loop's thread touches it.
//  - epoll knows a connection by its file descriptor (`data.fd`), never by a pointer; the loop
//  looks
//    the descriptor up in its table, so an event for a connection that is gone finds nothing.
//  - The loop registers the descriptor with epoll after the connection is in its table, and removes
//    it (EPOLL_CTL_DEL, checked) before the connection leaves the table; only then is it destroyed,
//    and its `UniqueFd` closes the descriptor.
//  - New connections are taken from the inbox after a batch of events is handled, so a descriptor
//    number reused by the kernel can never meet a stale event of the same batch.
//
// Why loops and no thread pool: one blocking thread per connection cost ~19 us of CPU per request
// (a third in context switches) against ~12 us on loops; cutcalc's handlers compute for
// microseconds (the largest polygon program ~0.1 s), so they run on the loop thread.

#include <atomic>
#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <httplib.h>

#include "service/http_connection.h"
#include "service/http_framing.h"
#include "service/http_limits.h"

namespace cutcalc::service {

struct EventLoopSettings {
  std::size_t loops = 2;
  std::size_t keep_alive_max_requests = 10000;
  std::size_t max_connections = 10000;  // beyond: 503 and close
  HttpLimits limits;                    // framing and timers
  bool tcp_nodelay = true;
};

// A response the engine gives by itself, before any handler: a framing error (400), a body over
// the limit (413) or the connection cap (503). The connection closes after it.
struct EngineError {
  int status = 400;
  std::string_view detail;
  std::string_view method;  // empty when the request line was not read
  std::string_view target;
  std::string_view origin;  // the request's Origin field; empty when it was not read
};

class EventLoopEngine {
 public:
  // httplib's process_request() for one request read from `stream`.
  using ServeRequest =
      std::function<bool(httplib::Stream& stream, bool close_connection, bool& connection_closed)>;
  // The whole response (status line to body) for an engine error; it must say Connection: close.
  // Called on a loop thread or the accept thread.
  using RenderError = std::function<std::string(const EngineError& error)>;
  // True once the server has been stopped: idle connections close, responses say close.
  using Stopping = std::function<bool()>;

  EventLoopEngine(EventLoopSettings settings, ServeRequest serve, RenderError render_error,
                  Stopping stopping, ConnectionCounters& counters);
  EventLoopEngine(const EventLoopEngine&) = delete;
  EventLoopEngine& operator=(const EventLoopEngine&) = delete;
  // Closes every connection and joins the loops.
  ~EventLoopEngine();

  // Takes ownership of a connected socket (TCP, or any stream socket). Never blocks.
  void adopt(int sock);

  // After the server stopped accepting: waits until every request in flight has been answered
  // (idle connections are closed at once), or until `limit` passes. True when drained.
  bool drain(std::chrono::milliseconds limit) const;

  [[nodiscard]] std::size_t open_connections() const { return open_connections_.load(); }

 private:
  struct Connection;
  class Loop;

  const EventLoopSettings settings_;
  const ServeRequest serve_;
  const RenderError render_error_;
  const Stopping stopping_;
  ConnectionCounters& counters_;
  std::atomic<std::size_t> open_connections_{0};  // adopted and not yet closed
  std::atomic<std::size_t> next_loop_{0};
  std::vector<std::unique_ptr<Loop>> loops_;  // last: its threads use everything above
};

}  // namespace cutcalc::service
