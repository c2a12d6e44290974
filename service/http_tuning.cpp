#include "service/http_tuning.h"

#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <thread>
#include <utility>

#include "service/http_event_loop.h"

namespace cutcalc::service {
namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

// Blocking mode: idle keep-alive waits are cut into slices this long, to notice server stop and
// thread pressure.
constexpr milliseconds kIdleSlice{200};

milliseconds to_ms(time_t sec, time_t usec) {
  return milliseconds{static_cast<milliseconds::rep>(sec) * 1000 +
                      static_cast<milliseconds::rep>(usec) / 1000};
}

// Event-loop mode: httplib's accept loop hands each accepted socket to process_and_close_socket()
// through its task queue; TunedServer only passes the socket on to an event loop, which never
// blocks, so it runs right on the accept thread.
class InlineTaskQueue final : public httplib::TaskQueue {
 public:
  void enqueue(std::function<void()> fn) override { fn(); }
  void shutdown() override {}
};

// The protected listening socket of any httplib::Server (a pointer to member formed through a
// derived class may be applied to the base).
struct ListenSocketAccess : httplib::Server {
  static std::atomic<socket_t>& of(httplib::Server& server) {
    return server.*(&ListenSocketAccess::svr_sock_);
  }
};

ElasticThreadPool::Limits pool_limits(const HttpTuning& tuning) {
  ElasticThreadPool::Limits limits;
  limits.min_threads = effective_worker_threads(tuning);
  limits.max_threads = std::max(tuning.max_worker_threads, limits.min_threads);
  limits.max_queued = std::max<std::size_t>(tuning.max_pending_connections, 1);
  limits.idle_timeout = milliseconds{std::max(tuning.idle_thread_timeout_ms, 1L)};
  return limits;
}

}  // namespace

std::size_t effective_worker_threads(const HttpTuning& tuning) {
  if (tuning.worker_threads > 0) return tuning.worker_threads;
  const std::size_t cores = std::max(1U, std::thread::hardware_concurrency());
  return std::max<std::size_t>(8, 2 * cores);
}

std::size_t effective_event_loop_threads(const HttpTuning& tuning) {
  if (tuning.event_loop_threads > 0) return tuning.event_loop_threads;
  return std::max(1U, std::thread::hardware_concurrency());
}

TunedServer::TunedServer() : load_(std::make_shared<PoolLoad>()) {}

// The engine (loops and their threads) goes before httplib::Server's members it calls into.
TunedServer::~TunedServer() { engine_.reset(); }

void TunedServer::configure(const HttpTuning& tuning) {
  tcp_nodelay_on_accept_ = tuning.tcp_nodelay;
  request_timeout_ms_ = std::max(tuning.request_timeout_ms, 0L);
  const auto limits = pool_limits(tuning);
  shed_at_busy_threads_ = tuning.shed_keep_alive_at_busy_threads > 0
                              ? tuning.shed_keep_alive_at_busy_threads
                              : std::max<std::size_t>(limits.max_threads * 3 / 4, 1);
  engine_.reset();
  if (!tuning.event_loop) {
    new_task_queue = [limits, load = load_] { return new ElasticThreadPool(limits, load); };
    return;
  }
  EventLoopSettings settings;
  settings.loops = effective_event_loop_threads(tuning);
  settings.read_timeout = to_ms(read_timeout_sec_, read_timeout_usec_);
  settings.write_timeout = to_ms(write_timeout_sec_, write_timeout_usec_);
  settings.keep_alive_timeout =
      milliseconds{static_cast<milliseconds::rep>(keep_alive_timeout_sec_) * 1000};
  settings.request_timeout = milliseconds{request_timeout_ms_};
  settings.keep_alive_max_requests = keep_alive_max_count_;
  settings.max_body_bytes = tuning.max_body_bytes;
  settings.tcp_nodelay = tuning.tcp_nodelay;
  settings.blocking_threads = limits;
  // A few threads suffice for what the loops hand over; more start on demand.
  settings.blocking_threads.min_threads =
      tuning.worker_threads > 0 ? tuning.worker_threads : std::size_t{2};
  engine_ = std::make_unique<EventLoopEngine>(
      settings,
      [this](httplib::Stream& stream, bool close_connection, bool& connection_closed) {
        return process_request(stream, close_connection, connection_closed, nullptr);
      },
      [this] { return stopping(); }, counters_, load_);
  new_task_queue = [] { return new InlineTaskQueue(); };
}

bool TunedServer::drain(std::chrono::milliseconds limit) {
  return engine_ == nullptr || engine_->drain(limit);
}

bool TunedServer::under_pressure() const {
  return shed_at_busy_threads_ > 0 && load_->busy_threads.load() >= shed_at_busy_threads_;
}

bool TunedServer::process_and_close_socket(socket_t sock) {
  if (engine_) {
    engine_->adopt(sock);
    return true;
  }
  return serve_blocking_connection(sock);
}

bool TunedServer::serve_blocking_connection(socket_t sock) {
  bool ret = false;
  counters_.connections.fetch_add(1, std::memory_order_relaxed);
  try {
    if (tcp_nodelay_on_accept_) {
      const int on = 1;
      ::setsockopt(sock, IPPROTO_TCP, TCP_NODELAY, &on, sizeof(on));
    }
    const auto keep_alive =
        milliseconds{static_cast<milliseconds::rep>(keep_alive_timeout_sec_) * 1000};
    ConnectionStream strm(sock, to_ms(read_timeout_sec_, read_timeout_usec_),
                          to_ms(write_timeout_sec_, write_timeout_usec_));

    for (std::size_t left = std::max<std::size_t>(keep_alive_max_count_, 1); left > 0; --left) {
      // Wait for the next request (or the first), in slices, like the library's keep_alive().
      if (!strm.has_buffered_input()) {
        const auto until = Clock::now() + keep_alive;
        bool ready = false;
        while (!stopping()) {
          const auto remaining = std::chrono::duration_cast<milliseconds>(until - Clock::now());
          if (remaining.count() <= 0) break;
          if (wait_socket(sock, POLLIN, std::min(remaining, kIdleSlice))) {
            ready = true;
            break;
          }
          if (under_pressure()) {
            counters_.keep_alive_shed.fetch_add(1, std::memory_order_relaxed);
            break;
          }
        }
        if (!ready) break;
      }
      if (stopping()) break;

      strm.start_request(request_timeout_ms_ > 0 ? Clock::now() + milliseconds{request_timeout_ms_}
                                                 : Clock::time_point::max());
      const bool close_connection = left == 1 || under_pressure();
      bool connection_closed = false;
      ret = process_request(strm, close_connection, connection_closed, nullptr);
      if (strm.timed_out()) {
        counters_.request_timeouts.fetch_add(1, std::memory_order_relaxed);
        strm.flush();
        ret = false;
        break;
      }
      if (!strm.flush()) ret = false;
      if (!ret) break;
      counters_.requests.fetch_add(1, std::memory_order_relaxed);
      if (connection_closed || close_connection) break;
    }
  } catch (...) {
    ret = false;  // nothing may escape into the pool; the socket is closed below
  }
  ::shutdown(sock, SHUT_RDWR);
  ::close(sock);
  return ret;
}

void apply_http_tuning(httplib::Server& server, const HttpTuning& tuning) {
  const auto split = [](long ms) {
    const long clamped = std::max(ms, 1L);
    return std::pair<time_t, time_t>{clamped / 1000, (clamped % 1000) * 1000};
  };
  const auto [read_s, read_us] = split(tuning.read_timeout_ms);
  const auto [write_s, write_us] = split(tuning.write_timeout_ms);
  server.set_read_timeout(read_s, read_us);
  server.set_write_timeout(write_s, write_us);
  server.set_keep_alive_max_count(std::max<std::size_t>(tuning.keep_alive_max_requests, 1));
  server.set_keep_alive_timeout(std::max(tuning.keep_alive_timeout_s, 0L));
  server.set_payload_max_length(tuning.max_body_bytes);
  // Set on the listening socket; Linux copies it to every accepted socket.
  server.set_tcp_nodelay(tuning.tcp_nodelay);

  if (auto* tuned = dynamic_cast<TunedServer*>(&server)) {
    tuned->configure(tuning);  // after the setters: it reads them
    return;
  }
  server.new_task_queue = [limits = pool_limits(tuning)] {
    return new ElasticThreadPool(limits, std::make_shared<PoolLoad>());
  };
}

int bind_with_backlog(httplib::Server& server, const char* host, int port, int listen_backlog) {
  int bound = port;
  if (port == 0) {
    bound = server.bind_to_any_port(host);
    if (bound < 0) return -1;
  } else if (!server.bind_to_port(host, port)) {
    return -1;
  }
  // The library listened with its compiled-in backlog of 5; listen() again on the same socket
  // only changes the backlog (Linux; the kernel caps it at net.core.somaxconn).
  const socket_t sock = ListenSocketAccess::of(server).load();
  if (sock == INVALID_SOCKET || ::listen(sock, std::max(listen_backlog, 1)) != 0) return -1;
  return bound;
}

}  // namespace cutcalc::service
