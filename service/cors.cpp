#include "service/cors.h"

#include <algorithm>

namespace cutcalc::service {

CorsPolicy::CorsPolicy(std::vector<std::string> allowed_origins)
    : origins_(std::move(allowed_origins)) {}

bool CorsPolicy::allows(std::string_view origin) const {
  return !origin.empty() && std::any_of(origins_.begin(), origins_.end(), [origin](const auto& o) {
    return o == "*" || o == origin;
  });
}

void CorsPolicy::decorate(const httplib::Request& req, httplib::Response& res) const {
  if (origins_.empty()) {
    return;
  }
  // Caches must keep answers for different origins apart.
  res.set_header("Vary", "Origin");
  const std::string origin = req.get_header_value("Origin");
  if (!allows(origin)) {
    return;
  }
  res.set_header("Access-Control-Allow-Origin", origin);
  res.set_header("Access-Control-Expose-Headers", "X-Request-Id, Content-Disposition");
}

void CorsPolicy::answer_options(httplib::Response& res, const std::string& allow) {
  res.status = 204;
  res.set_header("Allow", allow);
  if (res.has_header("Access-Control-Allow-Origin")) {
    res.set_header("Access-Control-Allow-Methods", allow);
    res.set_header("Access-Control-Allow-Headers", "Content-Type, Accept, X-Request-Id");
    res.set_header("Access-Control-Max-Age", "600");
  }
}

}  // namespace cutcalc::service
