#include "service/http_connection.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>

#include <algorithm>
#include <array>
#include <cstring>

namespace cutcalc::service {
namespace {

SocketAddresses::Address address_of(int fd, bool peer) {
  SocketAddresses::Address address;
  sockaddr_storage storage{};
  socklen_t length = sizeof(storage);
  auto* generic = reinterpret_cast<sockaddr*>(&storage);
  if ((peer ? ::getpeername(fd, generic, &length) : ::getsockname(fd, generic, &length)) != 0) {
    return address;
  }
  std::array<char, INET6_ADDRSTRLEN> text{};
  if (storage.ss_family == AF_INET) {
    const auto* in = reinterpret_cast<const sockaddr_in*>(&storage);
    if (::inet_ntop(AF_INET, &in->sin_addr, text.data(), text.size()) == nullptr) return address;
    address.port = ntohs(in->sin_port);
  } else if (storage.ss_family == AF_INET6) {
    const auto* in6 = reinterpret_cast<const sockaddr_in6*>(&storage);
    if (::inet_ntop(AF_INET6, &in6->sin6_addr, text.data(), text.size()) == nullptr) {
      return address;
    }
    address.port = ntohs(in6->sin6_port);
  } else {
    return address;
  }
  address.ip = text.data();
  return address;
}

thread_local std::string_view t_framed_body;

}  // namespace

std::string_view framed_request_body() { return t_framed_body; }

FramedRequestBody::FramedRequestBody(std::string_view body) : previous_(t_framed_body) {
  t_framed_body = body;
}

FramedRequestBody::~FramedRequestBody() { t_framed_body = previous_; }

const SocketAddresses::Address& SocketAddresses::peer() const {
  if (!peer_) peer_ = address_of(fd_, true);
  return *peer_;
}

const SocketAddresses::Address& SocketAddresses::local() const {
  if (!local_) local_ = address_of(fd_, false);
  return *local_;
}

ssize_t ConnectionStream::read(char* ptr, size_t size) {
  const std::size_t n = std::min(size, request_.size());
  if (n > 0) std::memcpy(ptr, request_.data(), n);
  request_.remove_prefix(n);
  return static_cast<ssize_t>(n);
}

ssize_t ConnectionStream::write(const char* ptr, size_t size) {
  output_.append(ptr, size);
  return static_cast<ssize_t>(size);
}

void ConnectionStream::get_remote_ip_and_port(std::string& ip, int& port) const {
  ip = addresses_.peer().ip;
  port = addresses_.peer().port;
}

void ConnectionStream::get_local_ip_and_port(std::string& ip, int& port) const {
  ip = addresses_.local().ip;
  port = addresses_.local().port;
}

}  // namespace cutcalc::service
