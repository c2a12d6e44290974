#include "service/listener.h"

#include <netdb.h>
#include <poll.h>
#include <sys/eventfd.h>
#include <sys/socket.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <thread>

namespace cutcalc::service {

Listener::Listener() : wake_(::eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK)) {}

int Listener::open(const ListenSettings& settings) {
  error_.clear();
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_flags = AI_PASSIVE | AI_NUMERICSERV;
  addrinfo* found = nullptr;
  const std::string service = std::to_string(settings.port);
  if (const int rc = ::getaddrinfo(settings.host.c_str(), service.c_str(), &hints, &found);
      rc != 0) {
    error_ = std::string("cannot resolve the host: ") + ::gai_strerror(rc);
    return -1;
  }
  for (const addrinfo* address = found; address != nullptr; address = address->ai_next) {
    UniqueFd sock(::socket(address->ai_family, address->ai_socktype | SOCK_CLOEXEC | SOCK_NONBLOCK,
                           address->ai_protocol));
    if (!sock.valid()) {
      error_ = std::strerror(errno);
      continue;
    }
    // SO_REUSEADDR lets a restarted server bind while old connections sit in TIME_WAIT; on Linux
    // it never lets two sockets listen on one port (SO_REUSEPORT does, hence only on request).
    const int on = 1;
    ::setsockopt(sock.get(), SOL_SOCKET, SO_REUSEADDR, &on, sizeof(on));
    if (settings.reuse_port) ::setsockopt(sock.get(), SOL_SOCKET, SO_REUSEPORT, &on, sizeof(on));
    if (::bind(sock.get(), address->ai_addr, address->ai_addrlen) != 0) {
      error_ = errno == EADDRINUSE
                   ? "the address is already in use (another process listens on it; "
                     "--reuse-port shares a port on purpose)"
                   : std::strerror(errno);
      continue;
    }
    if (::listen(sock.get(), std::max(settings.backlog, 1)) != 0) {
      error_ = std::strerror(errno);
      continue;
    }
    sockaddr_storage bound{};
    socklen_t length = sizeof(bound);
    if (::getsockname(sock.get(), reinterpret_cast<sockaddr*>(&bound), &length) != 0) {
      error_ = std::strerror(errno);
      continue;
    }
    const int port = bound.ss_family == AF_INET6
                         ? ntohs(reinterpret_cast<const sockaddr_in6*>(&bound)->sin6_port)
                         : ntohs(reinterpret_cast<const sockaddr_in*>(&bound)->sin_port);
    ::freeaddrinfo(found);
    socket_ = std::move(sock);
    return port;
  }
  ::freeaddrinfo(found);
  if (error_.empty()) error_ = "no address to bind";
  return -1;
}

bool Listener::run(const std::function<void(int sock)>& adopt) {
  if (!socket_.valid() || !wake_.valid()) {
    closed_.store(true);
    return false;
  }
  using Clock = std::chrono::steady_clock;
  std::array<pollfd, 2> watched{pollfd{socket_.get(), POLLIN, 0}, pollfd{wake_.get(), POLLIN, 0}};
  for (;;) {
    const std::int64_t stop_at = stop_at_ns_.load();
    const std::int64_t now =
        std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now().time_since_epoch())
            .count();
    if (stop_at <= now) break;
    // Once a stop is set the wake-up has done its job (it stays readable): the listener alone,
    // until the stop time.
    const bool stopping = stop_at != INT64_MAX;
    const int timeout_ms =
        stopping ? static_cast<int>(std::min<std::int64_t>((stop_at - now) / 1000000 + 1, 1000))
                 : -1;
    if (::poll(watched.data(), stopping ? 1 : 2, timeout_ms) < 0 && errno != EINTR) break;
    if ((watched[0].revents & POLLIN) == 0) continue;
    for (;;) {
      const int sock = ::accept4(socket_.get(), nullptr, nullptr, SOCK_CLOEXEC);
      if (sock >= 0) {
        adopt(sock);
        continue;
      }
      if (errno == EINTR || errno == ECONNABORTED) continue;
      if (errno == EMFILE || errno == ENFILE || errno == ENOBUFS || errno == ENOMEM) {
        // Out of descriptors or memory: the pending connection stays queued; try again shortly
        // rather than spin on a readable listener.
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
      break;  // EAGAIN: all accepted
    }
  }
  socket_.reset();
  closed_.store(true);
  return true;
}

void Listener::stop(std::chrono::milliseconds delay) {
  if (stop_requested_.exchange(true)) return;
  // The wake-up first: once run() sees the stop time, its caller may destroy this listener and
  // its descriptors, so stop() must not touch them after the store.
  const std::uint64_t one = 1;
  [[maybe_unused]] const auto n = ::write(wake_.get(), &one, sizeof(one));
  const auto at = std::chrono::steady_clock::now() + delay;
  stop_at_ns_.store(
      std::chrono::duration_cast<std::chrono::nanoseconds>(at.time_since_epoch()).count());
}

}  // namespace cutcalc::service
