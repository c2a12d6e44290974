#include "service/http_connection.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <limits>

namespace cutcalc::service {
namespace {

using std::chrono::milliseconds;

constexpr std::size_t kInitialInput = 4096;
// Blocking mode flushes gathered output once it reaches this size.
constexpr std::size_t kOutputFlushBytes = 64 * 1024;

void address_of(int sock, bool peer, std::string& ip, int& port) {
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

bool iequals(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; };
           return lower(x) == lower(y);
         });
}

}  // namespace

bool wait_socket(int sock, short events, milliseconds timeout) {
  pollfd pfd{sock, events, 0};
  const int ms = static_cast<int>(
      std::clamp<milliseconds::rep>(timeout.count(), 0, std::numeric_limits<int>::max()));
  for (;;) {
    const int n = ::poll(&pfd, 1, ms);
    if (n > 0) return true;
    if (n == 0 || errno != EINTR) return false;
  }
}

ConnectionStream::ConnectionStream(int sock, milliseconds read_timeout, milliseconds write_timeout)
    : sock_(sock), read_timeout_(read_timeout), write_timeout_(write_timeout) {}

void ConnectionStream::start_request(Clock::time_point deadline) {
  deadline_ = deadline;
  timed_out_ = false;
}

ConnectionStream::Fill ConnectionStream::fill_nonblocking(std::size_t limit) {
  if (in_off_ == in_len_) in_off_ = in_len_ = 0;
  if (in_len_ == in_.size()) {  // no room after the unread bytes
    if (in_off_ > 0) {
      std::memmove(in_.data(), in_.data() + in_off_, in_len_ - in_off_);
      in_len_ -= in_off_;
      in_off_ = 0;
    } else if (in_len_ >= limit) {
      return Fill::full;
    } else {
      in_.resize(std::min(std::max(in_.size() * 2, kInitialInput), limit));
    }
  }
  const ssize_t n = recv_some(in_.data() + in_len_, in_.size() - in_len_, MSG_DONTWAIT);
  if (n > 0) {
    in_len_ += static_cast<std::size_t>(n);
    return Fill::data;
  }
  if (n == 0) return Fill::eof;
  return errno == EAGAIN || errno == EWOULDBLOCK ? Fill::again : Fill::error;
}

void ConnectionStream::release_idle_buffers() {
  if (!has_buffered_input() && in_.size() > kInitialInput) {
    std::vector<char>().swap(in_);
    in_off_ = in_len_ = 0;
  }
  if (!has_pending_output() && out_.capacity() > kInitialInput) {
    std::string().swap(out_);
    out_off_ = 0;
  }
}

bool ConnectionStream::flush() {
  if (!has_pending_output()) return true;
  const bool ok = send_all(out_.data() + out_off_, out_.size() - out_off_);
  out_.clear();
  out_off_ = 0;
  return ok;
}

ConnectionStream::Flush ConnectionStream::flush_nonblocking() {
  while (has_pending_output()) {
    const ssize_t n =
        ::send(sock_, out_.data() + out_off_, out_.size() - out_off_, MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno == EAGAIN || errno == EWOULDBLOCK ? Flush::again : Flush::error;
    }
    out_off_ += static_cast<std::size_t>(n);
  }
  out_.clear();
  out_off_ = 0;
  return Flush::done;
}

bool ConnectionStream::is_readable() const {
  if (has_buffered_input()) return true;
  if (nonblocking_only_) return false;
  return wait_socket(sock_, POLLIN, read_wait());
}

bool ConnectionStream::is_writable() const {
  return nonblocking_only_ || wait_socket(sock_, POLLOUT, write_timeout_);
}

ssize_t ConnectionStream::read(char* ptr, size_t size) {
  if (size == 0) return 0;
  if (has_buffered_input()) return take_buffered(ptr, size);
  if (nonblocking_only_) return -1;  // the request was not complete after all
  if (!flush()) return -1;
  if (in_.size() < kInitialInput) in_.resize(kInitialInput);
  // Large reads go straight to the caller's buffer, small ones through in_.
  const bool direct = size >= in_.size();
  char* const into = direct ? ptr : in_.data();
  const size_t room = direct ? size : in_.size();
  // Usually the bytes are already there (the idle wait polled for them): try first, poll after.
  ssize_t n = recv_some(into, room, MSG_DONTWAIT);
  if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
    const auto wait = read_wait();
    if (wait.count() <= 0 || !wait_socket(sock_, POLLIN, wait)) {
      if (Clock::now() >= deadline_) timed_out_ = true;
      return -1;
    }
    n = recv_some(into, room, MSG_DONTWAIT);
  }
  if (n <= 0 || direct) return n;
  in_off_ = 0;
  in_len_ = static_cast<std::size_t>(n);
  return take_buffered(ptr, size);
}

ssize_t ConnectionStream::write(const char* ptr, size_t size) {
  if (!nonblocking_only_ && out_.size() - out_off_ + size > kOutputFlushBytes) {
    if (!flush()) return -1;
    if (size >= kOutputFlushBytes) return send_all(ptr, size) ? static_cast<ssize_t>(size) : -1;
  }
  out_.append(ptr, size);
  return static_cast<ssize_t>(size);
}

void ConnectionStream::get_remote_ip_and_port(std::string& ip, int& port) const {
  if (!peer_known_) {
    address_of(sock_, true, peer_ip_, peer_port_);
    peer_known_ = true;
  }
  ip = peer_ip_;
  port = peer_port_;
}

void ConnectionStream::get_local_ip_and_port(std::string& ip, int& port) const {
  if (!local_known_) {
    address_of(sock_, false, local_ip_, local_port_);
    local_known_ = true;
  }
  ip = local_ip_;
  port = local_port_;
}

milliseconds ConnectionStream::read_wait() const {
  if (deadline_ == Clock::time_point::max()) return read_timeout_;
  const auto left = std::chrono::duration_cast<milliseconds>(deadline_ - Clock::now());
  return std::min(read_timeout_, std::max(left, milliseconds{0}));
}

ssize_t ConnectionStream::take_buffered(char* ptr, size_t size) {
  const std::size_t n = std::min(size, in_len_ - in_off_);
  std::memcpy(ptr, in_.data() + in_off_, n);
  in_off_ += n;
  return static_cast<ssize_t>(n);
}

ssize_t ConnectionStream::recv_some(char* ptr, size_t size, int flags) {
  for (;;) {
    const ssize_t n = ::recv(sock_, ptr, size, flags);
    if (n >= 0 || errno != EINTR) return n;
  }
}

bool ConnectionStream::send_all(const char* ptr, size_t size) {
  while (size > 0) {
    const ssize_t n = ::send(sock_, ptr, size, MSG_NOSIGNAL);
    if (n < 0) {
      if (errno == EINTR) continue;
      // SO_SNDTIMEO (the write timeout) expired, or the socket is non-blocking and full.
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

RequestReadiness classify_request(std::string_view input, std::size_t max_body_bytes) {
  using enum RequestReadiness;
  // Mirrors httplib 0.11.4's reading: the request line ends at the first '\n'; then lines up to
  // a line that is exactly "\r\n"; lines not ending in "\r\n" are skipped; a header is
  // "name:value" with the name compared as is (case-insensitively). Anything unusual about the
  // three headers that decide the body's length goes to a blocking thread, where the library
  // reads exactly as it always does.
  const std::size_t line_end = input.find('\n');
  if (line_end == std::string_view::npos) {
    return input.size() >= kMaxBufferedHead ? needs_thread : incomplete;
  }
  const std::string_view request_line = input.substr(0, line_end);
  const std::string_view method = request_line.substr(0, request_line.find(' '));

  std::size_t pos = line_end + 1;
  std::size_t head_length = 0;
  bool has_length = false;
  std::uint64_t content_length = 0;
  while (head_length == 0) {
    const std::size_t end = input.find('\n', pos);
    if (end == std::string_view::npos) {
      return input.size() >= kMaxBufferedHead ? needs_thread : incomplete;
    }
    const std::string_view line = input.substr(pos, end + 1 - pos);
    pos = end + 1;
    if (pos > kMaxBufferedHead) return needs_thread;
    if (line == "\r\n") {
      head_length = pos;
      break;
    }
    if (line.size() < 2 || line[line.size() - 2] != '\r') continue;  // skipped by httplib too
    const std::size_t colon = line.find(':');
    if (colon == std::string_view::npos) continue;
    const std::string_view name = line.substr(0, colon);
    if (iequals(name, "transfer-encoding") || iequals(name, "expect")) return needs_thread;
    if (iequals(name, "content-length")) {
      if (has_length) return needs_thread;  // duplicates: let the library decide
      std::string_view value = line.substr(colon + 1, line.size() - 2 - (colon + 1));
      const auto blank = [](char c) { return c == ' ' || c == '\t'; };
      while (!value.empty() && blank(value.front())) value.remove_prefix(1);
      while (!value.empty() && blank(value.back())) value.remove_suffix(1);
      if (value.empty() || value.size() > 18) return needs_thread;
      for (const char c : value) {
        if (c < '0' || c > '9') return needs_thread;
        content_length = content_length * 10 + static_cast<std::uint64_t>(c - '0');
      }
      has_length = true;
    }
  }

  if (!has_length) {
    // httplib reads a body until EOF for these methods when no length is given.
    const bool body_method = method == "POST" || method == "PUT" || method == "PATCH" ||
                             method == "DELETE" || method == "PRI";
    return body_method ? needs_thread : complete;
  }
  if (content_length > max_body_bytes) return needs_thread;  // httplib answers 413
  return input.size() - head_length >= content_length ? complete : incomplete;
}

}  // namespace cutcalc::service
