#include "support/engine_client.h"

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <string>
#include <thread>

namespace cutcalc::testing {

namespace {
constexpr int kPatienceMs =
    static_cast<int>(std::chrono::milliseconds(EngineClient::kPatience).count());
}

service::EventLoopSettings small_engine_settings(std::size_t pool_threads) {
  service::EventLoopSettings settings;
  settings.loops = 1;
  settings.pool.threads = pool_threads;
  settings.pool.nice_increment = 0;
  return settings;
}

std::string bare_engine_error(const service::EngineError& error) {
  return "HTTP/1.1 " + std::to_string(service::http_status(error.fault)) +
         " Engine\r\nContent-Length: 0\r\nConnection: close\r\n\r\n";
}

EngineClient::EngineClient(service::EventLoopEngine& engine) {
  int pair[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, pair) != 0) return;
  server_fd_ = pair[0];
  fd_ = pair[1];
  engine.adopt(pair[0]);
}

void EngineClient::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

void EngineClient::shut_down_writing() const { ::shutdown(fd_, SHUT_WR); }

void EngineClient::send(const std::string& bytes) const {
  std::size_t sent = 0;
  while (sent < bytes.size()) {
    const ssize_t n = ::send(fd_, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
    ASSERT_GT(n, 0);
    sent += static_cast<std::size_t>(n);
  }
}

ParsedResponses EngineClient::read_responses(std::size_t finals) {
  const auto until = std::chrono::steady_clock::now() + kPatience;
  while (std::chrono::steady_clock::now() < until) {
    const ParsedResponses parsed = parse_responses(bytes_);
    if (!parsed.error && parsed.finals() >= finals) return parsed;
    if (!read_some(kPatienceMs)) break;
  }
  return parse_responses(bytes_);
}

bool EngineClient::read_to_close() {
  const auto until = std::chrono::steady_clock::now() + kPatience;
  while (std::chrono::steady_clock::now() < until) {
    if (!read_some(kPatienceMs)) return closed_;
  }
  return false;
}

void EngineClient::read_slowly(std::size_t bytes, std::chrono::milliseconds pause) {
  while (read_some(kPatienceMs, bytes)) std::this_thread::sleep_for(pause);
}

const std::string& EngineClient::arrived_now() {
  read_some(0);
  return bytes_;
}

bool EngineClient::read_some(int timeout_ms, std::size_t at_most) {
  pollfd watched{fd_, POLLIN, 0};
  if (::poll(&watched, 1, timeout_ms) <= 0) return false;
  std::string buffer(at_most, '\0');
  const ssize_t n = ::recv(fd_, buffer.data(), buffer.size(), MSG_DONTWAIT);
  if (n <= 0) {
    closed_ = n == 0;
    return false;
  }
  bytes_.append(buffer.data(), static_cast<std::size_t>(n));
  return true;
}

}  // namespace cutcalc::testing
