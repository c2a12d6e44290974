#include "service/http_tuning.h"

#include "service/cpu_budget.h"

#include <sys/resource.h>
#include <sys/socket.h>

#include <algorithm>
#include <functional>
#include <string>

namespace cutcalc::service {
namespace {

// Descriptors kept back from the connection cap: listener, epoll and event fds, logs.
constexpr std::size_t kReservedDescriptors = 64;
constexpr std::size_t kMaxConnectionsCap = 65536;

static_assert(HttpLimits{}.max_request_line_bytes == CPPHTTPLIB_REQUEST_URI_MAX_LENGTH &&
                  HttpLimits{}.max_field_line_bytes == CPPHTTPLIB_HEADER_MAX_LENGTH,
              "the engine must never accept a line the HTTP library refuses");

// httplib's accept loop hands each accepted socket to process_and_close_socket() through its task
// queue; TunedServer only passes the socket on to an event loop, which never blocks, so it runs
// right on the accept thread.
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

std::string_view reason_phrase(int status) {
  switch (status) {
    case 400:
      return "Bad Request";
    case 413:
      return "Payload Too Large";
    case 503:
      return "Service Unavailable";
    default:
      return "Error";
  }
}

}  // namespace

std::size_t effective_event_loop_threads(const HttpTuning& tuning) {
  if (tuning.event_loop_threads > 0) return tuning.event_loop_threads;
  return read_cpu_budget().usable_cpus;
}

std::size_t effective_max_connections(const HttpTuning& tuning) {
  if (tuning.max_connections > 0) return tuning.max_connections;
  rlimit limit{};
  if (::getrlimit(RLIMIT_NOFILE, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) {
    return kMaxConnectionsCap;
  }
  const auto soft = static_cast<std::size_t>(limit.rlim_cur);
  return std::clamp(soft - std::min(soft, kReservedDescriptors), std::size_t{1},
                    kMaxConnectionsCap);
}

TunedServer::TunedServer(const HttpTuning& tuning, EventLoopEngine::RenderError render_error) {
  apply_http_tuning(*this, tuning);
  EventLoopSettings settings;
  settings.loops = effective_event_loop_threads(tuning);
  settings.limits = tuning.limits;
  settings.limits.write_timeout =
      std::max(tuning.limits.write_timeout, std::chrono::milliseconds{1});
  settings.keep_alive_max_requests = std::max<std::size_t>(tuning.keep_alive_max_requests, 1);
  settings.max_connections = effective_max_connections(tuning);
  settings.tcp_nodelay = tuning.tcp_nodelay;
  engine_ = std::make_unique<EventLoopEngine>(
      settings,
      [this](httplib::Stream& stream, bool close_connection, bool& connection_closed) {
        return process_request(stream, close_connection, connection_closed, nullptr);
      },
      std::move(render_error), [this] { return stopping(); }, counters_);
  new_task_queue = [] { return new InlineTaskQueue(); };
}

// The engine (loops and their threads) goes before httplib::Server's members it calls into.
TunedServer::~TunedServer() { engine_.reset(); }

bool TunedServer::drain(std::chrono::milliseconds limit) const { return engine_->drain(limit); }

bool TunedServer::process_and_close_socket(socket_t sock) {
  engine_->adopt(sock);
  return true;
}

void apply_http_tuning(httplib::Server& server, const HttpTuning& tuning) {
  server.set_keep_alive_max_count(std::max<std::size_t>(tuning.keep_alive_max_requests, 1));
  server.set_keep_alive_timeout(tuning.limits.keep_alive_timeout.count());
  server.set_payload_max_length(tuning.limits.max_body_bytes);
  // Set on the listening socket; Linux copies it to every accepted socket.
  server.set_tcp_nodelay(tuning.tcp_nodelay);
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

std::string closing_response(int status, std::string_view content_type, std::string_view body,
                             const httplib::Headers& headers) {
  std::string response = "HTTP/1.1 " + std::to_string(status) + " ";
  response.append(reason_phrase(status)).append("\r\nContent-Type: ").append(content_type);
  response.append("\r\nContent-Length: ").append(std::to_string(body.size()));
  response.append("\r\nConnection: close\r\n");
  for (const auto& [name, value] : headers) response.append(name + ": " + value + "\r\n");
  response.append("\r\n").append(body);
  return response;
}

}  // namespace cutcalc::service
