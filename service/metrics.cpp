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

}  // namespace cutcalc::service
