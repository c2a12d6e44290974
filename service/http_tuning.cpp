#include "service/http_tuning.h"

#include <sys/resource.h>

#include <algorithm>
#include <string>

#include "service/cpu_budget.h"

namespace cutcalc::service {
namespace {

// Descriptors kept back from the connection cap: listener, epoll and event fds, logs.
constexpr std::size_t kReservedDescriptors = 64;
constexpr std::size_t kMaxConnectionsCap = 65536;

}  // namespace

std::size_t effective_event_loop_threads(const HttpTuning& tuning) {
  if (tuning.event_loop_threads > 0) return tuning.event_loop_threads;
  return read_cpu_budget().usable_cpus;
}

std::size_t effective_max_connections(const HttpTuning& tuning) {
  if (tuning.max_connections > 0) return tuning.max_connections;
  rlimit limit{};
  if (::getrlimit(RLIMIT_NOFILE, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) {
    return kMaxConnectionsCap;
  }
  const auto soft = static_cast<std::size_t>(limit.rlim_cur);
  return std::clamp(soft - std::min(soft, kReservedDescriptors), std::size_t{1},
                    kMaxConnectionsCap);
}

EventLoopSettings event_loop_settings(const HttpTuning& tuning) {
  EventLoopSettings settings;
  settings.loops = effective_event_loop_threads(tuning);
  settings.limits = tuning.limits;
  settings.limits.write_timeout =
      std::max(tuning.limits.write_timeout, std::chrono::milliseconds{1});
  settings.keep_alive_max_requests = std::max<std::size_t>(tuning.keep_alive_max_requests, 1);
  settings.max_connections = effective_max_connections(tuning);
  settings.pool.threads =
      tuning.calculation_threads > 0 ? tuning.calculation_threads : settings.loops;
  settings.pool.queue_limit = tuning.calculation_queue_limit;
  settings.tcp_nodelay = tuning.tcp_nodelay;
  return settings;
}

std::string closing_response(const HttpResponse& response) {
  std::string out;
  write_response(response, false, ConnectionAfter::close, out);
  return out;
}

}  // namespace cutcalc::service
