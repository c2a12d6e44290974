#include "service/socket_addresses.h"

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

}  // namespace

const SocketAddresses::Address& SocketAddresses::peer() const {
  if (!peer_) peer_ = address_of(fd_, true);
  return *peer_;
}

const SocketAddresses::Address& SocketAddresses::local() const {
  if (!local_) local_ = address_of(fd_, false);
  return *local_;
}

}  // namespace cutcalc::service
