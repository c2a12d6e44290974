#include "service/http_tuning.h"

#include <sys/resource.h>

#include <algorithm>
#include <string>

#include "api/routes.h"
#include "service/cpu_budget.h"

namespace cutcalc::service {
namespace {

// Descriptors kept back from the connection cap: listener, epoll and event fds, logs.
constexpr std::size_t kReservedDescriptors = 64;
constexpr std::size_t kMaxConnectionsCap = 65536;

static_assert(kMinimumMemoryBudgetBytes >= kLargeBodyHeldTimes * api::kProgramBodyBytes,
              "the least work budget must hold the largest body a route takes");

}  // namespace

std::size_t effective_event_loop_threads(const HttpTuning& tuning) {
  if (tuning.event_loop_threads > 0) return tuning.event_loop_threads;
  return read_cpu_budget().usable_cpus;
}

std::size_t effective_max_connections(const HttpTuning& tuning,
                                      std::optional<std::uint64_t> memory_limit_bytes,
                                      std::size_t calculation_threads) {
  if (tuning.max_connections > 0) return tuning.max_connections;
  std::size_t cap = kMaxConnectionsCap;
  rlimit limit{};
  if (::getrlimit(RLIMIT_NOFILE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
    const auto soft = static_cast<std::size_t>(limit.rlim_cur);
    cap = std::min(cap, soft - std::min(soft, kReservedDescriptors));
  }
  if (memory_limit_bytes) {
    const std::uint64_t held = kProcessBaselineBytes + calculation_threads * kCalculationPeakBytes +
                               kMinimumMemoryBudgetBytes;
    const std::uint64_t usable = *memory_limit_bytes - std::min(*memory_limit_bytes, held);
    const std::uint64_t by_memory =
        std::max<std::uint64_t>(usable / std::max<std::size_t>(tuning.connection_memory_bytes, 1),
                                kMinimumMemoryConnections);
    cap = std::min<std::uint64_t>(cap, by_memory);
  }
  return std::max<std::size_t>(cap, 1);
}

std::uint64_t effective_memory_budget(const HttpTuning& tuning, std::size_t max_connections,
                                      std::size_t calculation_threads,
                                      std::optional<std::uint64_t> memory_limit_bytes) {
  const std::uint64_t limit = memory_limit_bytes.value_or(kDefaultMemoryLimitBytes);
  std::uint64_t held = kProcessBaselineBytes + calculation_threads * kCalculationPeakBytes;
  if (memory_limit_bytes) held += std::uint64_t{max_connections} * tuning.connection_memory_bytes;
  return std::max(limit - std::min(limit, held), kMinimumMemoryBudgetBytes);
}

EventLoopSettings event_loop_settings(const HttpTuning& tuning) {
  EventLoopSettings settings;
  settings.loops = effective_event_loop_threads(tuning);
  settings.limits = tuning.limits;
  settings.limits.write_timeout =
      std::max(tuning.limits.write_timeout, std::chrono::milliseconds{1});
  settings.keep_alive_max_requests = std::max<std::size_t>(tuning.keep_alive_max_requests, 1);
  settings.pool.threads =
      tuning.calculation_threads > 0 ? tuning.calculation_threads : settings.loops;
  settings.pool.queue_limit = tuning.calculation_queue_limit;
  const std::optional<std::uint64_t> memory_limit = tuning.memory_limit_bytes > 0
                                                        ? std::optional(tuning.memory_limit_bytes)
                                                        : read_memory_limit();
  settings.max_connections = effective_max_connections(tuning, memory_limit, settings.pool.threads);
  settings.memory_budget_bytes = effective_memory_budget(tuning, settings.max_connections,
                                                         settings.pool.threads, memory_limit);
  settings.tcp_nodelay = tuning.tcp_nodelay;
  return settings;
}

std::string closing_response(const HttpResponse& response) {
  std::string out;
  write_response(response, false, ConnectionAfter::close, out);
  return out;
}

}  // namespace cutcalc::service
