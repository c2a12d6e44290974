#include "service/metrics.h"

#include <sstream>

namespace cutcalc::service {

namespace {

// Methods as static labels; anything unusual is one label, so user input never becomes a key.
std::string_view method_label(std::string_view method) {
  for (const std::string_view known :
       {"GET", "HEAD", "POST", "PUT", "DELETE", "PATCH", "OPTIONS"}) {
    if (method == known) {
      return known;
    }
  }
  return "other";
}

}  // namespace

void Metrics::observe(std::string_view route, std::string_view method, int status, double seconds) {
  const std::lock_guard lock(mutex_);
  ++requests_[std::make_tuple(route, method_label(method), status)];
  Histogram& h = latency_[route];
  for (std::size_t i = 0; i < kBucketsSeconds.size(); ++i) {
    if (seconds <= kBucketsSeconds[i]) {
      ++h.buckets[i];
      break;
    }
  }
  ++h.count;
  h.sum_seconds += seconds;
}

std::string Metrics::render() const {
  std::ostringstream out;
  out << "# HELP cutcalc_http_requests_total HTTP requests answered, by route, method and status.\n"
         "# TYPE cutcalc_http_requests_total counter\n";
  const std::lock_guard lock(mutex_);
  for (const auto& [key, count] : requests_) {
    const auto& [route, method, status] = key;
    out << "cutcalc_http_requests_total{route=\"" << route << "\",method=\"" << method
        << "\",status=\"" << status << "\"} " << count << '\n';
  }
  out << "# HELP cutcalc_http_request_duration_seconds Time from routing to the response written.\n"
         "# TYPE cutcalc_http_request_duration_seconds histogram\n";
  for (const auto& [route, h] : latency_) {
    std::uint64_t cumulative = 0;
    for (std::size_t i = 0; i < kBucketsSeconds.size(); ++i) {
      cumulative += h.buckets[i];
      out << "cutcalc_http_request_duration_seconds_bucket{route=\"" << route << "\",le=\""
          << kBucketsSeconds[i] << "\"} " << cumulative << '\n';
    }
    out << "cutcalc_http_request_duration_seconds_bucket{route=\"" << route << "\",le=\"+Inf\"} "
        << h.count << '\n'
        << "cutcalc_http_request_duration_seconds_sum{route=\"" << route << "\"} " << h.sum_seconds
        << '\n'
        << "cutcalc_http_request_duration_seconds_count{route=\"" << route << "\"} " << h.count
        << '\n';
  }
  out << "# HELP cutcalc_http_requests_in_flight Requests being processed now.\n"
         "# TYPE cutcalc_http_requests_in_flight gauge\n"
         "cutcalc_http_requests_in_flight "
      << in_flight_.load(std::memory_order_relaxed) << '\n';
  return out.str();
}

std::string render_connection_metrics(const ConnectionCounters& counters,
                                      std::size_t open_connections, const MemoryBudget& budget) {
  struct Counter {
    const char* name;
    const char* help;
    const std::atomic<std::uint64_t>& value;
  };
  const Counter all[] = {
      {"cutcalc_http_connections_total", "Connections accepted.", counters.connections},
      {"cutcalc_http_engine_requests_total", "Requests framed and handed to the app.",
       counters.requests},
      {"cutcalc_http_framing_rejections_total",
       "Requests the engine answered 400/413 itself (malformed or ambiguous framing, body too "
       "large); each closed its connection.",
       counters.rejected_requests},
      {"cutcalc_http_request_timeouts_total",
       "Connections closed because a request did not arrive whole in time.",
       counters.request_timeouts},
      {"cutcalc_http_connections_refused_total", "Connections answered 503 at the connection cap.",
       counters.rejected_at_cap},
      {"cutcalc_http_large_bodies_refused_total",
       "Requests with a large body (a program to time) answered 503 with Retry-After because "
       "max_large_bodies others were being received.",
       counters.large_bodies_refused},
      {"cutcalc_http_epoll_failures_total", "epoll_ctl calls that failed (the connection closed).",
       counters.epoll_failures},
      {"cutcalc_calculation_pool_jobs_total",
       "Jobs started on the calculation pool: heavy calculations (programs), and the pieces of "
       "programs written as they are sent.",
       counters.calculations.jobs},
      {"cutcalc_calculation_pool_refused_total",
       "Heavy calculations answered 503 with Retry-After because the pool's queue was full.",
       counters.calculations.refused},
      {"cutcalc_calculation_timeouts_total",
       "Heavy calculations answered 503 with Retry-After because the calculation timeout passed "
       "(the calculation was stopped).",
       counters.calculation_timeouts},
      {"cutcalc_memory_budget_refused_total",
       "Requests answered 503 with Retry-After because the memory budget was spent: a large body "
       "before it was read, or a calculation before it was handed to the pool.",
       counters.memory_refused},
      {"cutcalc_calculations_abandoned_total",
       "Heavy calculations stopped because their connection closed before the answer.",
       counters.calculations_abandoned},
      {"cutcalc_streams_broken_total",
       "Programs sent as they are written whose writing failed after the status was sent: the "
       "connection was closed and the client saw a truncated chunked body.",
       counters.streams_broken},
  };
  std::ostringstream out;
  for (const Counter& counter : all) {
    out << "# HELP " << counter.name << ' ' << counter.help << "\n# TYPE " << counter.name
        << " counter\n"
        << counter.name << ' ' << counter.value.load(std::memory_order_relaxed) << '\n';
  }
  out << "# HELP cutcalc_calculation_pool_wait_seconds_total Time heavy calculations waited in "
         "the pool's queue, summed (divide by the jobs for the mean wait).\n"
         "# TYPE cutcalc_calculation_pool_wait_seconds_total counter\n"
         "cutcalc_calculation_pool_wait_seconds_total "
      << static_cast<double>(counters.calculations.wait_microseconds.load()) / 1e6 << '\n';
  out << "# HELP cutcalc_calculation_pool_queue_depth Heavy calculations waiting for a thread "
         "now.\n"
         "# TYPE cutcalc_calculation_pool_queue_depth gauge\n"
         "cutcalc_calculation_pool_queue_depth "
      << counters.calculations.queued.load() << '\n';
  out << "# HELP cutcalc_calculation_pool_running Heavy calculations running now.\n"
         "# TYPE cutcalc_calculation_pool_running gauge\n"
         "cutcalc_calculation_pool_running "
      << counters.calculations.running.load() << '\n';
  out << "# HELP cutcalc_http_large_bodies_receiving Requests receiving a body over the default "
         "limit now (a program to time); at most max_large_bodies.\n"
         "# TYPE cutcalc_http_large_bodies_receiving gauge\n"
         "cutcalc_http_large_bodies_receiving "
      << counters.large_bodies_receiving.load() << '\n';
  out << "# HELP cutcalc_http_connection_buffer_bytes Bytes the open connections hold in their "
         "buffers (as of the event loops' last sweep; idle connections hold none).\n"
         "# TYPE cutcalc_http_connection_buffer_bytes gauge\n"
         "cutcalc_http_connection_buffer_bytes "
      << counters.buffer_bytes.load() << '\n';
  out << "# HELP cutcalc_memory_budget_bytes The memory budget of the requests' work: large bodies "
         "and answers waiting for their clients.\n"
         "# TYPE cutcalc_memory_budget_bytes gauge\n"
         "cutcalc_memory_budget_bytes "
      << budget.capacity() << '\n';
  out << "# HELP cutcalc_memory_budget_used_bytes What the requests hold of the memory budget now "
         "(it may pass the budget by answers computed before it was spent).\n"
         "# TYPE cutcalc_memory_budget_used_bytes gauge\n"
         "cutcalc_memory_budget_used_bytes "
      << budget.used() << '\n';
  out << "# HELP cutcalc_http_open_connections Connections open now.\n"
         "# TYPE cutcalc_http_open_connections gauge\n"
         "cutcalc_http_open_connections "
      << open_connections << '\n';
  return out.str();
}

}  // namespace cutcalc::service
