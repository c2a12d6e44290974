#include "service/http_tuning.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <limits>
#include <string>
#include <thread>

namespace cutcalc::service {
namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

// Idle keep-alive waits are cut into slices this long, to notice server stop and thread pressure.
constexpr milliseconds kIdleSlice{200};
// Output is gathered up to this size before a send() (a response normally fits in one).
constexpr std::size_t kOutputFlushBytes = 64 * 1024;

int poll_ms(milliseconds timeout) {
  const auto ms = std::clamp<milliseconds::rep>(timeout.count(), 0,
                                                std::numeric_limits<int>::max());
  return static_cast<int>(ms);
}

// Waits until `sock` has `events` pending; false on timeout or error.
bool wait_socket(int sock, short events, milliseconds timeout) {
  pollfd pfd{sock, events, 0};
  for (;;) {
    const int n = ::poll(&pfd, 1, poll_ms(timeout));
    if (n > 0) return true;
    if (n == 0) return false;
    if (errno != EINTR) return false;
  }
}

milliseconds to_ms(time_t sec, time_t usec) {
  return milliseconds{static_cast<milliseconds::rep>(sec) * 1000 +
                      static_cast<milliseconds::rep>(usec) / 1000};
}

void peer_or_local(int sock, bool peer, std::string& ip, int& port) {
  sockaddr_storage addr{};
  socklen_t len = sizeof(addr);
  auto* sa = reinterpret_cast<sockaddr*>(&addr);
  if ((peer ? ::getpeername(sock, sa, &len) : ::getsockname(sock, sa, &len)) != 0) return;
  std::array<char, INET6_ADDRSTRLEN> text{};
  if (addr.ss_family == AF_INET) {
    const auto* in = reinterpret_cast<const sockaddr_in*>(&addr);
    if (::inet_ntop(AF_INET, &in->sin_addr, text.data(), text.size()) == nullptr) return;
    port = ntohs(in->sin_port);
  } else if (addr.ss_family == AF_INET6) {
    const auto* in6 = reinterpret_cast<const sockaddr_in6*>(&addr);
    if (::inet_ntop(AF_INET6, &in6->sin6_addr, text.data(), text.size()) == nullptr) return;
    port = ntohs(in6->sin6_port);
  } else {
    return;
  }
  ip = text.data();
}

// The Stream handed to httplib's process_request(): reads through a buffer that lives as long
// as the connection, gathers writes until flush() (or until the next read from the socket, so
// that e.g. "100 Continue" goes out before the body is awaited), and enforces a per-request
// deadline on top of the per-read timeout.
class ConnectionStream final : public httplib::Stream {
 public:
  ConnectionStream(int sock, milliseconds read_timeout, milliseconds write_timeout)
      : sock_(sock), read_timeout_(read_timeout), write_timeout_(write_timeout) {}

  bool has_buffered_input() const { return in_off_ < in_len_; }
  bool timed_out() const { return timed_out_; }
  void start_request(milliseconds budget) {
    has_deadline_ = budget.count() > 0;
    deadline_ = Clock::now() + budget;
  }

  bool is_readable() const override {
    return has_buffered_input() || wait_socket(sock_, POLLIN, read_wait());
  }
  bool is_writable() const override { return wait_socket(sock_, POLLOUT, write_timeout_); }

  ssize_t read(char* ptr, size_t size) override {
    if (size == 0) return 0;
    if (has_buffered_input()) return take_buffered(ptr, size);
    if (!flush()) return -1;
    // Large reads go straight to the caller's buffer, small ones through in_.
    const bool direct = size >= in_.size();
    char* const into = direct ? ptr : in_.data();
    const size_t room = direct ? size : in_.size();
    // Usually the bytes are already there (the idle wait polled for them): try first, poll after.
    ssize_t n = recv_some(into, room, MSG_DONTWAIT);
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
      const auto wait = read_wait();
      if (wait.count() <= 0 || !wait_socket(sock_, POLLIN, wait)) {
        if (has_deadline_ && Clock::now() >= deadline_) timed_out_ = true;
        return -1;
      }
      n = recv_some(into, room, MSG_DONTWAIT);
    }
    if (n <= 0 || direct) return n;
    in_off_ = 0;
    in_len_ = static_cast<std::size_t>(n);
    return take_buffered(ptr, size);
  }

  ssize_t write(const char* ptr, size_t size) override {
    if (out_.size() + size > kOutputFlushBytes) {
      if (!flush()) return -1;
      if (size >= kOutputFlushBytes) return send_all(ptr, size) ? static_cast<ssize_t>(size) : -1;
    }
    out_.append(ptr, size);
    return static_cast<ssize_t>(size);
  }

  bool flush() {
    if (out_.empty()) return true;
    const bool ok = send_all(out_.data(), out_.size());
    out_.clear();
    return ok;
  }

  void get_remote_ip_and_port(std::string& ip, int& port) const override {
    if (!peer_known_) {
      peer_or_local(sock_, true, peer_ip_, peer_port_);
      peer_known_ = true;
    }
    ip = peer_ip_;
    port = peer_port_;
  }
  void get_local_ip_and_port(std::string& ip, int& port) const override {
    if (!local_known_) {
      peer_or_local(sock_, false, local_ip_, local_port_);
      local_known_ = true;
    }
    ip = local_ip_;
    port = local_port_;
  }
  socket_t socket() const override { return sock_; }

 private:
  milliseconds read_wait() const {
    if (!has_deadline_) return read_timeout_;
    const auto left = std::chrono::duration_cast<milliseconds>(deadline_ - Clock::now());
    return std::min(read_timeout_, std::max(left, milliseconds{0}));
  }

  ssize_t take_buffered(char* ptr, size_t size) {
    const std::size_t n = std::min(size, in_len_ - in_off_);
    std::memcpy(ptr, in_.data() + in_off_, n);
    in_off_ += n;
    return static_cast<ssize_t>(n);
  }

  ssize_t recv_some(char* ptr, size_t size, int flags) {
    for (;;) {
      const ssize_t n = ::recv(sock_, ptr, size, flags);
      if (n >= 0 || errno != EINTR) return n;
    }
  }

  bool send_all(const char* ptr, size_t size) {
    while (size > 0) {
      const ssize_t n = ::send(sock_, ptr, size, MSG_NOSIGNAL);
      if (n < 0) {
        if (errno == EINTR) continue;
        // SO_SNDTIMEO (the write timeout) expired, or the socket was non-blocking and full.
        if ((errno == EAGAIN || errno == EWOULDBLOCK) &&
            wait_socket(sock_, POLLOUT, write_timeout_)) {
          continue;
        }
        return false;
      }
      ptr += n;
      size -= static_cast<size_t>(n);
    }
    return true;
  }

  int sock_;
  milliseconds read_timeout_;
  milliseconds write_timeout_;
  bool has_deadline_ = false;
  Clock::time_point deadline_{};
  bool timed_out_ = false;
  std::array<char, 8192> in_{};
  std::size_t in_off_ = 0;
  std::size_t in_len_ = 0;
  std::string out_;
  mutable bool peer_known_ = false;
  mutable std::string peer_ip_;
  mutable int peer_port_ = 0;
  mutable bool local_known_ = false;  // process_request asks for both on every request
  mutable std::string local_ip_;
  mutable int local_port_ = 0;
};

// The protected listening socket of any httplib::Server (a pointer to member formed through a
// derived class may be applied to the base).
struct ListenSocketAccess : httplib::Server {
  static std::atomic<socket_t>& of(httplib::Server& server) {
    return server.*(&ListenSocketAccess::svr_sock_);
  }
};

}  // namespace

std::size_t effective_worker_threads(const HttpTuning& tuning) {
  if (tuning.worker_threads > 0) return tuning.worker_threads;
  const std::size_t cores = std::max(1U, std::thread::hardware_concurrency());
  return std::max<std::size_t>(8, 2 * cores);
}

TunedServer::TunedServer() : load_(std::make_shared<PoolLoad>()) {}

TunedServer::~TunedServer() = default;

bool TunedServer::under_pressure() const {
  return shed_at_busy_threads_ > 0 && load_->busy_threads.load() >= shed_at_busy_threads_;
}

bool TunedServer::process_and_close_socket(socket_t sock) {
  bool ret = false;
  counters_.connections.fetch_add(1, std::memory_order_relaxed);
  try {
    if (tcp_nodelay_on_accept_) {
      const int on = 1;
      ::setsockopt(sock, IPPROTO_TCP, TCP_NODELAY, &on, sizeof(on));
    }
    const auto read_timeout = to_ms(read_timeout_sec_, read_timeout_usec_);
    const auto keep_alive = milliseconds{static_cast<milliseconds::rep>(keep_alive_timeout_sec_) * 1000};
    ConnectionStream strm(sock, read_timeout, to_ms(write_timeout_sec_, write_timeout_usec_));

    for (std::size_t left = std::max<std::size_t>(keep_alive_max_count_, 1); left > 0; --left) {
      // Wait for the next request (or the first), in slices, like the library's keep_alive().
      if (!strm.has_buffered_input()) {
        const auto until = Clock::now() + keep_alive;
        bool ready = false;
        while (svr_sock_ != INVALID_SOCKET) {
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
      if (svr_sock_ == INVALID_SOCKET) break;

      strm.start_request(milliseconds{request_timeout_ms_});
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

  ElasticThreadPool::Limits limits;
  limits.min_threads = effective_worker_threads(tuning);
  limits.max_threads = std::max(tuning.max_worker_threads, limits.min_threads);
  limits.max_queued = std::max<std::size_t>(tuning.max_pending_connections, 1);
  limits.idle_timeout = milliseconds{std::max(tuning.idle_thread_timeout_ms, 1L)};

  std::shared_ptr<PoolLoad> load;
  if (auto* tuned = dynamic_cast<TunedServer*>(&server)) {
    load = tuned->load_;
    tuned->tcp_nodelay_on_accept_ = tuning.tcp_nodelay;
    tuned->request_timeout_ms_ = std::max(tuning.request_timeout_ms, 0L);
    tuned->shed_at_busy_threads_ = tuning.shed_keep_alive_at_busy_threads > 0
                                       ? tuning.shed_keep_alive_at_busy_threads
                                       : std::max<std::size_t>(limits.max_threads * 3 / 4, 1);
  } else {
    load = std::make_shared<PoolLoad>();
  }
  server.new_task_queue = [limits, load] { return new ElasticThreadPool(limits, load); };
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
