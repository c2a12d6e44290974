#pragma once
// The HTTP front: TunedServer (cpp-httplib's Server, its connections served by the event-loop
// engine of service/http_event_loop.h) and the settings that tune it.
//
// Why not the library's own connection handling (Debian 12's libcpp-httplib 0.11.4, whose
// defaults are compiled into the shared library; bench/http_rootcause.sh reproduces each number):
//  - it serves each connection on one thread of a fixed pool of max(8, cores - 1) for the
//    connection's whole life: with 8 idle keep-alive connections open, a new request waited 5 s;
//  - it waits for the next request in a 10 ms poll + 1 ms sleep loop: 300 idle connections burnt
//    1.45 s of CPU per 3 s (the loops: 0.01-0.06 s);
//  - it sends headers and body in two send()s: with Nagle on, 43 ms per request on a keep-alive
//    connection (delayed ACK); TCP_NODELAY and one send() per response fix it;
//  - it listens with a backlog of 5: wrk -c256 overflowed it; bind_with_backlog() uses 1024;
//  - it frames requests leniently (two Content-Lengths, Transfer-Encoding with Content-Length,
//    404/405 before the body is read): the engine frames them strictly instead.

#include <chrono>
#include <cstddef>
#include <memory>

#include <httplib.h>

#include "service/http_connection.h"
#include "service/http_event_loop.h"
#include "service/http_limits.h"

namespace cutcalc::service {

struct HttpTuning {
  std::size_t event_loop_threads = 0;           // 0: one per usable CPU (cpu_budget.h)
  std::size_t keep_alive_max_requests = 10000;  // requests per keep-alive connection
  HttpLimits limits;
  std::size_t max_connections = 0;  // beyond: 503; 0: from the descriptor limit
  int listen_backlog = 1024;
  bool tcp_nodelay = true;
};

// Event loop threads for `tuning` on this machine (resolves event_loop_threads == 0).
std::size_t effective_event_loop_threads(const HttpTuning& tuning);
// Open connections allowed (resolves max_connections == 0: the soft RLIMIT_NOFILE less a reserve
// for the listener, logs and the like, at most 65536).
std::size_t effective_max_connections(const HttpTuning& tuning);

// httplib::Server whose accepted connections go to the engine: it overrides the library's
// virtual process_and_close_socket(), as the library's own SSLServer does. Routing, request
// parsing and response writing stay the library's (process_request()).
class TunedServer : public httplib::Server {
 public:
  TunedServer(const HttpTuning& tuning, EventLoopEngine::RenderError render_error);
  ~TunedServer() override;

  // After stop(): waits until the requests in flight have been answered, at most `limit`.
  // True when none is left.
  bool drain(std::chrono::milliseconds limit) const;
  const ConnectionCounters& counters() const { return counters_; }
  std::size_t open_connections() const { return engine_->open_connections(); }
  // Serves a connected stream socket as if it had been accepted (takes ownership).
  void adopt_connection(int sock) { engine_->adopt(sock); }

 private:
  bool process_and_close_socket(socket_t sock) override;
  bool stopping() const { return svr_sock_ == INVALID_SOCKET; }

  ConnectionCounters counters_;
  std::unique_ptr<EventLoopEngine> engine_;
};

// The library's runtime settings from the tuning (keep-alive, payload limit, TCP_NODELAY on the
// listening socket); TunedServer applies them itself.
void apply_http_tuning(httplib::Server& server, const HttpTuning& tuning);

// Binds host:port with the tuned listen backlog (the library's own is compiled in at 5).
// port 0 picks a free port. Returns the bound port, or -1. Then call listen_after_bind().
int bind_with_backlog(httplib::Server& server, const char* host, int port, int listen_backlog);

// A complete response that closes the connection: status line, Content-Type, Content-Length,
// Connection: close, the given extra headers, and the body. For the engine's own errors.
std::string closing_response(int status, std::string_view content_type, std::string_view body,
                             const httplib::Headers& headers = {});

}  // namespace cutcalc::service
