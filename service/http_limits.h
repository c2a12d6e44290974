#pragma once
// The limits of one request and one connection, stated once: the engine's framing and timers
// (http_framing.h, http_event_loop.h) and the numbers README.md and openapi.yaml give
// (tests/service/http_limits_test.cpp reads them there).

#include <chrono>
#include <cstddef>

namespace cutcalc::service {

struct HttpLimits {
  std::size_t max_head_bytes = 16 * 1024;  // request line + fields (and trailer fields); over: 400
  std::size_t max_body_bytes = 64 * 1024;  // content, after chunked decoding; over: 413
  std::size_t max_fields = 100;            // header fields in one request
  // One line of the head at most (the request line; a field line).
  std::size_t max_request_line_bytes = 8192;
  std::size_t max_field_line_bytes = 8192;
  std::chrono::seconds keep_alive_timeout{5};  // an idle keep-alive connection is closed after it
  // A whole request (head + body) from its first byte; 0: none. Also how long a shutdown waits
  // for the requests in flight (at least 1 s).
  std::chrono::milliseconds request_timeout{10000};
  std::chrono::milliseconds write_timeout{5000};  // a response waiting for the client to read it
  // After a connection's last response: how long its unread input is read and dropped, so that the
  // close does not reset the connection before the client has read the response (RFC 9112 9.6).
  std::chrono::milliseconds linger_time{1000};
  // Pipelined requests are served until this much of their responses waits for the socket.
  std::size_t max_pending_output_bytes = 256 * 1024;

  // Unread input a connection buffers at most: the largest request that can be framed (head,
  // body and chunk framing, which counts against the head's allowance).
  [[nodiscard]] std::size_t max_buffered_bytes() const {
    return 2 * max_head_bytes + max_body_bytes;
  }
};

}  // namespace cutcalc::service
