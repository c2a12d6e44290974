#pragma once
// What the HTTP library reads a request from and writes its response into: memory, never the
// socket. The engine (service/http_event_loop.h) frames a request completely before the library
// sees it (service/http_framing.h), so reading can never block or run past the request, and the
// response is gathered so that it leaves in as few send()s as the socket allows.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include <httplib.h>

namespace cutcalc::service {

// The addresses of a connected socket, looked up once per connection (the library asks for both
// on every request).
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

class ConnectionStream final : public httplib::Stream {
 public:
  // `request`: one framed request (library_request()); `output`: where the response goes.
  ConnectionStream(std::string_view request, std::string& output, const SocketAddresses& addresses)
      : request_(request), output_(output), addresses_(addresses) {}

  bool is_readable() const override { return !request_.empty(); }
  bool is_writable() const override { return true; }
  // Past the end of the request: 0, the end of the stream (the library never waits for more).
  ssize_t read(char* ptr, size_t size) override;
  ssize_t write(const char* ptr, size_t size) override;
  void get_remote_ip_and_port(std::string& ip, int& port) const override;
  void get_local_ip_and_port(std::string& ip, int& port) const override;
  // No socket: the library would refuse a descriptor >= FD_SETSIZE with a 500 (a guard for its
  // select()-based waits, which this stream never needs).
  socket_t socket() const override { return INVALID_SOCKET; }

 private:
  std::string_view request_;
  std::string& output_;
  const SocketAddresses& addresses_;
};

// The body of the request the calling thread is serving, framed by the engine before the library
// parses anything (empty outside a request and for a request without one). The library reads a
// body only after its pre-routing handler; the app answers a calculation there, from this view,
// which saves the library's regex routing and its copy of the body on every request.
std::string_view framed_request_body();

// Makes `body` the calling thread's framed_request_body() for this object's lifetime.
class FramedRequestBody {
 public:
  explicit FramedRequestBody(std::string_view body);
  FramedRequestBody(const FramedRequestBody&) = delete;
  FramedRequestBody& operator=(const FramedRequestBody&) = delete;
  ~FramedRequestBody();

 private:
  std::string_view previous_;
};

// Counters kept by the engine (monotonic, for metrics).
struct ConnectionCounters {
  std::atomic<std::uint64_t> connections{0};
  std::atomic<std::uint64_t> requests{0};
  std::atomic<std::uint64_t> rejected_requests{0};  // framing errors answered by the engine
  std::atomic<std::uint64_t> request_timeouts{0};   // request_timeout exceeded (slowloris)
  std::atomic<std::uint64_t> rejected_at_cap{0};    // 503: max_connections open
  std::atomic<std::uint64_t> epoll_failures{0};     // epoll_ctl refused; the connection closed
};

}  // namespace cutcalc::service
