#pragma once
// The HTTP engine's counters (service/http_event_loop.h), rendered by service/metrics.h.

#include <atomic>
#include <cstdint>

#include "service/work_pool.h"

namespace cutcalc::service {

// Counters kept by the engine (monotonic, for metrics).
struct ConnectionCounters {
  std::atomic<std::uint64_t> connections{0};
  std::atomic<std::uint64_t> requests{0};
  std::atomic<std::uint64_t> rejected_requests{0};       // framing errors answered by the engine
  std::atomic<std::uint64_t> request_timeouts{0};        // request_timeout exceeded (slowloris)
  std::atomic<std::uint64_t> rejected_at_cap{0};         // 503: max_connections open
  std::atomic<std::uint64_t> large_bodies_refused{0};    // 503: max_large_bodies being received
  std::atomic<std::uint64_t> large_bodies_receiving{0};  // gauge: bodies over the default limit
  std::atomic<std::uint64_t> epoll_failures{0};          // epoll_ctl refused; the connection closed
  WorkPoolCounters calculations;                         // the calculation pool
  std::atomic<std::uint64_t> calculation_timeouts{0};    // 503: calculation_timeout passed
  std::atomic<std::uint64_t> calculations_abandoned{0};  // the client went while on the pool
  std::atomic<std::uint64_t> memory_refused{0};          // 503: the memory budget was spent
  std::atomic<std::uint64_t> streams_broken{0};          // a body written as sent threw: cut short
  // Bytes the open connections hold in their buffers, as of the loops' last sweep (gauge): an idle
  // connection gives its buffers back, so this is about the connections busy now.
  std::atomic<std::uint64_t> buffer_bytes{0};
};

}  // namespace cutcalc::service
