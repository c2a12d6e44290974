#pragma once
// The HTTP engine's settings (service/http_event_loop.h, service/listener.h) and how they resolve
// on this machine.
//
// Why an engine of our own and not cpp-httplib's connection handling (Debian 12's libcpp-httplib
// 0.11.4, whose defaults are compiled into the shared library; bench/http_rootcause.sh reproduces
// each number):
//  - it serves each connection on one thread of a fixed pool of max(8, cores - 1) for the
//    connection's whole life: with 8 idle keep-alive connections open, a new request waited 5 s;
//  - it waits for the next request in a 10 ms poll + 1 ms sleep loop: 300 idle connections burnt
//    1.45 s of CPU per 3 s (the loops: 0.01-0.06 s);
//  - it sends headers and body in two send()s: with Nagle on, 43 ms per request on a keep-alive
//    connection (delayed ACK); TCP_NODELAY and one send() per response fix it;
//  - it listens with a backlog of 5 (wrk -c256 overflowed it) and with SO_REUSEPORT, so a second
//    server on the same port started silently and shared the traffic;
//  - it frames requests leniently (two Content-Lengths, Transfer-Encoding with Content-Length,
//    404/405 before the body is read): the engine frames them strictly instead;
//  - parsing each head a second time and writing the response through its Stream cost about 5 of
//    12.7 us per request (issue 14's profile): the engine parses once.

#include <cstddef>
#include <cstdint>
#include <optional>

#include "service/http_event_loop.h"
#include "service/http_limits.h"

namespace cutcalc::service {

struct HttpTuning {
  std::size_t event_loop_threads = 0;           // 0: one per usable CPU (cpu_budget.h)
  std::size_t calculation_threads = 0;          // the pool for heavy calculations; 0: as the loops
  std::size_t calculation_queue_limit = 16;     // calculations waiting for a thread; beyond: 503
  std::size_t keep_alive_max_requests = 10000;  // requests per keep-alive connection
  HttpLimits limits;
  std::size_t max_connections = 0;  // beyond: 503; 0: from the memory and descriptor limits
  // What one open connection is budgeted against the memory limit (an idle one costs a few KiB of
  // kernel and engine state; a busy one its buffers).
  std::size_t connection_memory_bytes = 16 * 1024;
  // The memory limit both the connection cap and the memory budget follow: 0, the cgroup's
  // memory.max (without one, kDefaultMemoryLimitBytes for the budget, and no memory bound on the
  // connection cap).
  std::uint64_t memory_limit_bytes = 0;
  int listen_backlog = 1024;
  bool reuse_port = false;  // SO_REUSEPORT: let other processes listen on the same port
  bool tcp_nodelay = true;
};

// Event loop threads for `tuning` on this machine (resolves event_loop_threads == 0).
std::size_t effective_event_loop_threads(const HttpTuning& tuning);
inline constexpr std::uint64_t kDefaultMemoryLimitBytes = 256ULL * 1024 * 1024;
// What the process holds besides the connections, the calculations and the budget: the binary,
// the page, the allocator's slack.
inline constexpr std::uint64_t kProcessBaselineBytes = 32ULL * 1024 * 1024;
// What one calculation may hold while it runs, at most one per pool thread: the largest polygon
// program timed took 48 MiB above the idle process (README.md, "Running").
inline constexpr std::uint64_t kCalculationPeakBytes = 64ULL * 1024 * 1024;
// The least budget of the requests' work: the largest body a route takes (api::kProgramBodyBytes,
// 32 MiB) counted at kLargeBodyHeldTimes. With less, that body could never be accepted: every try
// would be a 503 with Retry-After, forever.
inline constexpr std::uint64_t kMinimumMemoryBudgetBytes = 64ULL * 1024 * 1024;
// The least connection cap a memory limit gives: a limit too small for its calculations (a
// 128 MiB pod with two calculation threads) still takes connections.
inline constexpr std::size_t kMinimumMemoryConnections = 1024;

// Open connections allowed. max_connections == 0 resolves to the smaller of what the memory limit
// (the cgroup's, `memory_limit_bytes`; none: no bound) holds at connection_memory_bytes each
// after the process baseline, a peak per calculation thread and the least work budget (at least
// kMinimumMemoryConnections), and the soft RLIMIT_NOFILE less a reserve for the listener, logs
// and the like; at most 65536, at least 1. So at the cap a new connection gets 503, never an OOM
// kill, and the work budget keeps room for the largest body.
std::size_t effective_max_connections(const HttpTuning& tuning,
                                      std::optional<std::uint64_t> memory_limit_bytes,
                                      std::size_t calculation_threads);
// The memory budget of the requests' work (service/memory_budget.h): the memory limit (none:
// kDefaultMemoryLimitBytes) less the process baseline, the calculations running and, under a
// real limit, what the connection cap lets the connections hold; at least the minimum.
std::uint64_t effective_memory_budget(const HttpTuning& tuning, std::size_t max_connections,
                                      std::size_t calculation_threads,
                                      std::optional<std::uint64_t> memory_limit_bytes);
// The engine's settings for `tuning` on this machine.
EventLoopSettings event_loop_settings(const HttpTuning& tuning);

// A complete response that closes the connection, for the engine's own errors.
std::string closing_response(const HttpResponse& response);

}  // namespace cutcalc::service
