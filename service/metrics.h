#pragma once
// Request metrics in the Prometheus text format: counts by route, method and status; latency
// histogram by route; requests in flight. Routes are a fixed set, so label cardinality is bounded.

#include <array>
#include <atomic>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <string_view>
#include <tuple>

#include "service/engine_counters.h"
#include "service/memory_budget.h"

namespace cutcalc::service {

class Metrics {
 public:
  // Upper bounds of the latency buckets, seconds (+Inf is implicit).
  static constexpr std::array<double, 13> kBucketsSeconds = {
      0.0001, 0.00025, 0.0005, 0.001, 0.0025, 0.005, 0.01, 0.025, 0.05, 0.1, 0.25, 1.0, 5.0};

  // `route` must outlive the Metrics (a route table entry or a literal).
  void observe(std::string_view route, std::string_view method, int status, double seconds);
  void enter() { in_flight_.fetch_add(1, std::memory_order_relaxed); }
  void leave() { in_flight_.fetch_sub(1, std::memory_order_relaxed); }
  [[nodiscard]] std::string render() const;

 private:
  struct Histogram {
    std::array<std::uint64_t, kBucketsSeconds.size()> buckets{};  // non-cumulative counts
    std::uint64_t count = 0;
    double sum_seconds = 0.0;
  };

  mutable std::mutex mutex_;
  // Keys point to route labels that live as long as the service and to static method names, so
  // recording a request allocates nothing after the first of its kind.
  std::map<std::tuple<std::string_view, std::string_view, int>, std::uint64_t> requests_;
  std::map<std::string_view, Histogram> latency_;
  std::atomic<std::int64_t> in_flight_{0};
};

// The HTTP engine's connection counters (service/engine_counters.h) in the same format.
std::string render_connection_metrics(const ConnectionCounters& counters,
                                      std::size_t open_connections, const MemoryBudget& budget);

}  // namespace cutcalc::service
