#pragma once
// How the HTTP front is tuned: threads, keep-alive, timeouts, limits, backlog. Every field has a
// default that serves well on a small machine; service/config.cpp fills it from flags and env.
//
// Why (measured here on Debian 12's libcpp-httplib 0.11.4, whose defaults are compiled into the
// shared library: CPPHTTPLIB_* macros in our code change nothing, only the runtime setters and
// the virtual process_and_close_socket() do; bench/http_rootcause.sh reproduces every number):
//  - tcp_nodelay: the library sends the status line + headers and the body with two send()s;
//    with Nagle on, the body waits for the ACK of the headers, which the client delays ~40 ms:
//    43 ms per request, 38 requests/s on one keep-alive connection (0.6 delayed ACKs per
//    request); with TCP_NODELAY ~12k requests/s. TunedServer also sends a response in one send().
//  - threads: the library serves each connection on one thread for its whole life, from a fixed
//    pool of max(8, cores - 1); with 8 idle keep-alive connections open, a new request waited
//    5.0 s (the keep-alive timeout). Elastic, capped pool: service/elastic_thread_pool.h.
//  - idle keep-alive: the library waits for the next request in a 10 ms poll + 1 ms sleep loop:
//    300 idle connections burnt 1.45 s of CPU per 3 s; TunedServer: 0.01-0.06 s.
//  - listen_backlog: the library listens with a backlog of 5; wrk -c256 overflowed it
//    (600-1100 ListenOverflows, ~250 SYN retransmits, 0.9-1.4 s worst latency);
//    bind_with_backlog() re-listens with 1024: no overflow.
//  - event_loop: one blocking thread per connection costs ~19-23 us of CPU per request (a third
//    in context switches) against ~12-14 us on the event loops (nginx: ~8 us).

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>

#include <httplib.h>

#include "service/elastic_thread_pool.h"
#include "service/http_connection.h"

namespace cutcalc::service {

struct HttpTuning {
  std::size_t worker_threads = 0;               // threads kept ready; 0: max(8, 2 x cores)
  std::size_t max_worker_threads = 512;         // hard cap on connection-serving threads
  std::size_t keep_alive_max_requests = 10000;  // requests per keep-alive connection
  long keep_alive_timeout_s = 5;                // idle keep-alive connection closed after this
  long read_timeout_ms = 5000;                  // longest wait for any single read from a socket
  long write_timeout_ms = 5000;                 // longest wait for any single write to a socket
  std::size_t max_body_bytes = 64 * 1024;       // larger bodies: 413
  int listen_backlog = 1024;
  bool tcp_nodelay = true;
  // Added with the elastic pool and TunedServer (comments above each field):
  // TunedServer serves from epoll loops (see below); false: one blocking thread per connection.
  bool event_loop = true;
  // Event loop threads; 0: one per core.
  std::size_t event_loop_threads = 0;
  // Connections or requests waiting for a thread at the cap; beyond, accept() pauses (blocking
  // mode: the kernel's backlog holds them) or the request is answered 503 (event-loop mode).
  std::size_t max_pending_connections = 1024;
  // Threads above worker_threads exit when idle this long.
  long idle_thread_timeout_ms = 30000;
  // TunedServer: a whole request (head + body) must arrive within this, from its first byte
  // (slowloris); 0: no limit beyond read_timeout_ms per read.
  long request_timeout_ms = 10000;
  // TunedServer, blocking mode: from this many busy threads on, idle keep-alive connections are
  // closed and responses say Connection: close; 0: 3/4 of max_worker_threads.
  std::size_t shed_keep_alive_at_busy_threads = 0;
};

// Threads kept ready for `tuning` on this machine (resolves worker_threads == 0).
std::size_t effective_worker_threads(const HttpTuning& tuning);
// Event loop threads for `tuning` on this machine (resolves event_loop_threads == 0).
std::size_t effective_event_loop_threads(const HttpTuning& tuning);

class EventLoopEngine;

// httplib::Server with its per-connection loop replaced (it overrides the library's virtual
// process_and_close_socket(), as the library's own SSLServer does); routing, parsing and
// response writing stay the library's (process_request()).
//
// Event-loop mode (HttpTuning::event_loop, the default; service/http_event_loop.h): accepted
// connections go to epoll loops (one per core); a request that has fully arrived is served on
// the loop thread; requests needing blocking reads go to a bounded elastic pool of threads
// (worker_threads .. max_worker_threads) and their connection comes back to the loop after.
// Idle keep-alive connections and slow clients hold no thread.
//
// Blocking mode (event_loop = false): one thread of the elastic pool per connection, as stock
// httplib, but idle keep-alive connections wait in a blocking poll() instead of the library's
// 10 ms poll + 1 ms sleep loop (90 wake-ups a second per idle connection), and when the pool
// runs short of threads (shed_keep_alive_at_busy_threads) idle keep-alive connections are
// closed within 200 ms and responses say Connection: close, so waiting connections get a thread.
//
// Both modes: a request's head and body must arrive within request_timeout_ms (slowloris); a
// response leaves in one send() (the library sends headers and body separately); input read
// ahead is kept across the requests of a connection (pipelining).
//
// apply_http_tuning() configures it; a TunedServer that was never tuned runs the blocking mode
// with the library's default settings.
class TunedServer : public httplib::Server {
 public:
  TunedServer();
  ~TunedServer() override;

  const PoolLoad& pool_load() const { return *load_; }

  // After stop(): waits until the requests in flight have been answered, at most `limit`.
  // True when none is left. (Blocking mode needs no wait: its pool joins them on stop.)
  bool drain(std::chrono::milliseconds limit);
  const ConnectionCounters& counters() const { return counters_; }

 private:
  friend void apply_http_tuning(httplib::Server& server, const HttpTuning& tuning);

  void configure(const HttpTuning& tuning);
  bool process_and_close_socket(socket_t sock) override;
  bool serve_blocking_connection(socket_t sock);
  bool under_pressure() const;
  bool stopping() const { return svr_sock_ == INVALID_SOCKET; }

  std::shared_ptr<PoolLoad> load_;
  ConnectionCounters counters_;
  std::unique_ptr<EventLoopEngine> engine_;  // event-loop mode
  bool tcp_nodelay_on_accept_ = false;
  long request_timeout_ms_ = 0;           // 0: none
  std::size_t shed_at_busy_threads_ = 0;  // 0: never
};

// Applies the tuning to a server before it binds: timeouts, keep-alive, payload limit,
// TCP_NODELAY and the elastic thread pool; for a TunedServer also its connection handling.
void apply_http_tuning(httplib::Server& server, const HttpTuning& tuning);

// Binds host:port with the tuned listen backlog (the library's own is compiled in at 5).
// port 0 picks a free port. Returns the bound port, or -1. Then call listen_after_bind().
int bind_with_backlog(httplib::Server& server, const char* host, int port, int listen_backlog);

}  // namespace cutcalc::service
