#pragma once
// Event loops for TunedServer: connections wait for their next request in epoll instead of
// holding a thread each, and a request that is completely buffered is served right on the loop
// thread (httplib's process_request() reading from the buffer, never from the socket). Anything
// else (a request that needs blocking reads: chunked, Expect: 100-continue, no Content-Length on
// a POST, oversized; or a response the socket cannot take at once) is handed to a thread of a
// bounded ElasticThreadPool, served there exactly as stock httplib would, and the connection then
// returns to its loop.
//
// Why: with one blocking thread per connection, every request costs a sleep and a wake-up of
// that thread (measured: ~19 us of CPU per request, a third of it in context switches, against
// ~7 us for nginx); idle keep-alive connections and slowloris clients each pin a thread. On a
// loop, one epoll_wait() returns many ready connections, an idle connection costs a few KiB, and
// a slow request costs nothing until it is complete (deadline: request_timeout).
//
// Handlers run on the loop threads, so they must not block for long (cutcalc's handlers compute
// for microseconds).

#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

#include <httplib.h>

#include "service/elastic_thread_pool.h"
#include "service/http_connection.h"

namespace cutcalc::service {

struct EventLoopSettings {
  std::size_t loops = 2;
  std::chrono::milliseconds read_timeout{5000};
  std::chrono::milliseconds write_timeout{5000};
  std::chrono::milliseconds keep_alive_timeout{5000};
  std::chrono::milliseconds request_timeout{10000};  // 0: none
  std::size_t keep_alive_max_requests = 10000;
  std::size_t max_body_bytes = 64 * 1024;
  bool tcp_nodelay = true;
  ElasticThreadPool::Limits blocking_threads;
};

class EventLoopEngine {
 public:
  // httplib's process_request() for one request on `stream`.
  using ServeRequest =
      std::function<bool(httplib::Stream& stream, bool close_connection, bool& connection_closed)>;
  // True once the server has been stopped: connections are closed, no request is started.
  using Stopping = std::function<bool()>;

  EventLoopEngine(EventLoopSettings settings, ServeRequest serve, Stopping stopping,
                  ConnectionCounters& counters, std::shared_ptr<PoolLoad> load);
  EventLoopEngine(const EventLoopEngine&) = delete;
  EventLoopEngine& operator=(const EventLoopEngine&) = delete;
  // Finishes the blocking threads' work, then closes every connection and joins the loops.
  ~EventLoopEngine();

  // Takes ownership of an accepted socket. Never blocks.
  void adopt(int sock);

  // After the server stopped accepting: waits until every request in flight has been answered
  // (idle connections are closed at once), or until `limit` passes. True when drained.
  bool drain(std::chrono::milliseconds limit);

 private:
  struct Connection;
  class Loop;
  enum class Outcome { idle, wait_input, to_thread, close };

  Outcome serve_nonblocking(Connection& connection);
  void serve_blocking(const std::shared_ptr<Connection>& connection);
  void park(std::shared_ptr<Connection> connection);
  bool hand_to_thread(std::shared_ptr<Connection> connection);

  const EventLoopSettings settings_;
  const ServeRequest serve_;
  const Stopping stopping_;
  ConnectionCounters& counters_;
  std::unique_ptr<ElasticThreadPool> pool_;
  std::vector<std::unique_ptr<Loop>> loops_;
  std::atomic<std::size_t> next_loop_{0};
  std::atomic<std::size_t> open_connections_{0};  // adopted and not yet closed
};

}  // namespace cutcalc::service
