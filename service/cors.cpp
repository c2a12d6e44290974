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

std::vector<ResponseHeader> CorsPolicy::headers_for(std::string_view origin,
                                                    bool origin_unread) const {
  std::vector<ResponseHeader> headers;
  if (origins_.empty()) {
    return headers;
  }
  // Caches must keep answers for different origins apart.
  headers.push_back({"Vary", "Origin"});
  const bool any = std::find(origins_.begin(), origins_.end(), "*") != origins_.end();
  if (origin.empty() && origin_unread && any) {
    headers.push_back({"Access-Control-Allow-Origin", "*"});
  } else if (allows(origin)) {
    headers.push_back({"Access-Control-Allow-Origin", std::string(origin)});
  } else {
    return headers;
  }
  headers.push_back({"Access-Control-Expose-Headers", "X-Request-Id, Content-Disposition"});
  return headers;
}

void CorsPolicy::decorate(std::string_view origin, HttpResponse& res) const {
  if (origins_.empty()) return;
  for (ResponseHeader& header : headers_for(origin, false)) {
    res.headers.push_back(std::move(header));
  }
}

std::vector<ResponseHeader> CorsPolicy::rejection_headers(std::string_view origin) const {
  return headers_for(origin, origin.empty());
}

void CorsPolicy::answer_options(HttpResponse& res, const std::string& allow) {
  res.status = 204;
  res.set_header("Allow", allow);
  if (res.has_header("Access-Control-Allow-Origin")) {
    res.set_header("Access-Control-Allow-Methods", allow);
    res.set_header("Access-Control-Allow-Headers", "Content-Type, Accept, X-Request-Id");
    res.set_header("Access-Control-Max-Age", "600");
  }
}

}  // namespace cutcalc::service
