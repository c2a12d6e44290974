#pragma once
// The limits of one request and one connection, stated once: the engine's framing and timers
// (http_framing.h, http_event_loop.h) and the numbers README.md and openapi.yaml give
// (tests/service/http_limits_test.cpp reads them there).

#include <chrono>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace cutcalc::service {

struct HttpLimits {
  std::size_t max_head_bytes = 16 * 1024;  // request line + fields (and trailer fields); over: 400
  std::size_t max_body_bytes = 64 * 1024;  // content, after chunked decoding; over: 413
  std::size_t max_fields = 100;            // header fields in one request
  // One line of the head at most (the request line; a field line).
  std::size_t max_request_line_bytes = 8192;
  std::size_t max_field_line_bytes = 8192;
  // An idle keep-alive connection is closed after it: above the idle timeouts of the usual proxies
  // and load balancers (nginx's upstream keepalive_timeout and cloud load balancers: 60 s), so
  // that a proxy never reuses a connection in the instant cutcalc closes it.
  std::chrono::seconds keep_alive_timeout{75};
  // At SIGTERM: how long /readyz answers 503 while the listener still accepts and every response
  // says Connection: close (a health checker polling every 1 s marks the instance down after 2
  // failures, with a margin), before the listener closes.
  std::chrono::milliseconds lame_duck{3000};
  // After the listener has closed: how long a keep-alive connection that has been idle since
  // before may still bring one more request (answered with Connection: close).
  std::chrono::milliseconds drain_idle_grace{1000};
  // A whole request (head + body) from its first byte; 0: none. Also how long a shutdown waits
  // for the requests in flight (at least 1 s).
  std::chrono::milliseconds request_timeout{10000};
  std::chrono::milliseconds write_timeout{5000};  // a response waiting for the client to read it
  // ... unless the client read at least this rate meanwhile (the socket's queue shrank): a slow
  // reader of a program of many megabytes keeps its connection, a stalled one does not.
  std::size_t min_download_bytes_per_s = 1024;
  // A calculation on the pool, from its hand-over (queue wait included) to its answer: past it the
  // client gets 503 with Retry-After and the calculation is stopped at its next check. Far above
  // the largest program's time (README.md, "Running"), so only a stuck or runaway job meets it.
  std::chrono::milliseconds calculation_timeout{30000};
  // After a connection's last response: how long its unread input is read and dropped, so that the
  // close does not reset the connection before the client has read the response (RFC 9112 9.6).
  std::chrono::milliseconds linger_time{1000};
  // Pipelined requests are served until this much of their responses waits for the socket.
  std::size_t max_pending_output_bytes = 256 * 1024;

  // Paths whose route row takes larger bodies (api::CalculationRoute::max_body_bytes: a whole
  // program to time), with their limit; every other target keeps max_body_bytes.
  std::vector<std::pair<std::string, std::size_t>> large_body_routes;
  // Requests that may buffer a body above max_body_bytes at once (all loops together); one more
  // is answered 503 with Retry-After before its body is read.
  std::size_t max_large_bodies = 4;
  // A large body's transfer is given request_timeout plus its length at this rate.
  std::size_t min_upload_bytes_per_s = 1000 * 1000;

  // The body limit of a request target (its path: the query is ignored).
  [[nodiscard]] std::size_t body_limit_for(std::string_view target) const {
    const std::string_view path = target.substr(0, target.find('?'));
    for (const auto& [route, limit] : large_body_routes) {
      if (path == route) return limit;
    }
    return max_body_bytes;
  }
  // Unread input a connection buffers at most: the largest request that can be framed (head,
  // body and chunk framing, which counts against the head's allowance), for a body limit.
  [[nodiscard]] std::size_t max_buffered_bytes(std::size_t body_limit) const {
    return 2 * max_head_bytes + body_limit;
  }
  [[nodiscard]] std::size_t max_buffered_bytes() const {
    return max_buffered_bytes(max_body_bytes);
  }
};

}  // namespace cutcalc::service
