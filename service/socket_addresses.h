#pragma once
// The addresses of a connection's socket (service/http_event_loop.h keeps one per connection).

#include <optional>
#include <string>
#include <string_view>

namespace cutcalc::service {

// The addresses of a connected socket, looked up once per connection and only when asked for
// (the access log's remote address).
class SocketAddresses {
 public:
  explicit SocketAddresses(int fd) : fd_(fd) {}
  struct Address {
    std::string ip;  // empty for a non-IP socket (e.g. a socketpair)
    int port = 0;
  };
  const Address& peer() const;
  const Address& local() const;

 private:
  int fd_;
  mutable std::optional<Address> peer_;
  mutable std::optional<Address> local_;
};

}  // namespace cutcalc::service
