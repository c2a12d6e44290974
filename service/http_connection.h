#pragma once
// One accepted HTTP connection as TunedServer serves it: the httplib::Stream handed to
// httplib's process_request(), and a conservative check of whether a complete request is
// already buffered (so that it can be served without ever blocking).

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <httplib.h>

namespace cutcalc::service {

// Counters kept by TunedServer (monotonic, for metrics).
struct ConnectionCounters {
  std::atomic<std::uint64_t> connections{0};
  std::atomic<std::uint64_t> requests{0};
  std::atomic<std::uint64_t> blocking_handoffs{0};  // requests served on a blocking thread
  std::atomic<std::uint64_t> keep_alive_shed{0};    // idle keep-alive closed under thread pressure
  std::atomic<std::uint64_t> request_timeouts{0};   // request_timeout_ms exceeded (slowloris)
  std::atomic<std::uint64_t> rejected_at_cap{0};    // 503: no blocking thread could be had
};

// Reads through a buffer that lives as long as the connection (pipelined bytes are kept),
// gathers writes until flush() so that a response leaves in one send(), and enforces a
// per-request deadline on top of the per-read timeout.
//
// Blocking mode (default): read() waits (poll) up to the read timeout / request deadline, and a
// read from the socket first flushes pending output (so "100 Continue" goes out before the body
// is awaited). Non-blocking mode: read() returns buffered bytes only, -1 when none are left,
// and write() only gathers; used when the whole request is known to be buffered.
class ConnectionStream final : public httplib::Stream {
 public:
  using Clock = std::chrono::steady_clock;

  ConnectionStream(int sock, std::chrono::milliseconds read_timeout,
                   std::chrono::milliseconds write_timeout);

  void set_nonblocking_only(bool on) { nonblocking_only_ = on; }
  void start_request(Clock::time_point deadline);  // time_point::max(): no deadline
  bool timed_out() const { return timed_out_; }

  bool has_buffered_input() const { return in_off_ < in_len_; }
  std::string_view buffered_input() const { return {in_.data() + in_off_, in_len_ - in_off_}; }
  // One non-blocking recv() into the buffer, growing it up to `limit` bytes of unread input.
  enum class Fill { data, eof, again, full, error };
  Fill fill_nonblocking(std::size_t limit);
  void release_idle_buffers();  // frees grown buffers of an idle connection

  bool has_pending_output() const { return out_off_ < out_.size(); }
  bool flush();  // blocking (up to the write timeout per send); false on error
  enum class Flush { done, again, error };
  Flush flush_nonblocking();

  bool is_readable() const override;
  bool is_writable() const override;
  ssize_t read(char* ptr, size_t size) override;
  ssize_t write(const char* ptr, size_t size) override;
  void get_remote_ip_and_port(std::string& ip, int& port) const override;
  void get_local_ip_and_port(std::string& ip, int& port) const override;
  socket_t socket() const override { return sock_; }

 private:
  std::chrono::milliseconds read_wait() const;
  ssize_t take_buffered(char* ptr, size_t size);
  ssize_t recv_some(char* ptr, size_t size, int flags);
  bool send_all(const char* ptr, size_t size);

  int sock_;
  std::chrono::milliseconds read_timeout_;
  std::chrono::milliseconds write_timeout_;
  bool nonblocking_only_ = false;
  Clock::time_point deadline_ = Clock::time_point::max();
  bool timed_out_ = false;
  std::vector<char> in_;
  std::size_t in_off_ = 0;
  std::size_t in_len_ = 0;
  std::string out_;
  std::size_t out_off_ = 0;
  mutable bool peer_known_ = false;  // process_request asks for both addresses on every request
  mutable std::string peer_ip_;
  mutable int peer_port_ = 0;
  mutable bool local_known_ = false;
  mutable std::string local_ip_;
  mutable int local_port_ = 0;
};

// Whether `input` starts with a request that process_request() can serve from the buffer alone.
enum class RequestReadiness {
  incomplete,    // wait for more bytes
  complete,      // head and body are buffered: serve without blocking
  needs_thread,  // chunked, Expect, no Content-Length on a method with a body, oversized or odd:
                 // leave it to the library's blocking reads (same behaviour as stock httplib)
};
RequestReadiness classify_request(std::string_view input, std::size_t max_body_bytes);

// Largest request head the non-blocking path buffers; longer heads go to a blocking thread.
inline constexpr std::size_t kMaxBufferedHead = 16 * 1024;

// Waits until `sock` has `events` pending; false on timeout or error.
bool wait_socket(int sock, short events, std::chrono::milliseconds timeout);

}  // namespace cutcalc::service
