#pragma once
// Cross-origin access for browser front ends: only the configured origins (none by default) get
// CORS headers; preflight requests are answered without reaching a handler.

#include <string>
#include <string_view>
#include <vector>

#include "service/http_response.h"

namespace cutcalc::service {

class CorsPolicy {
 public:
  explicit CorsPolicy(std::vector<std::string> allowed_origins);

  // Adds the CORS response headers when the request's Origin is allowed. Call it once per
  // response: every header it sets is appended.
  void decorate(std::string_view origin, HttpResponse& res) const;

  // The same headers for an answer the engine gives by itself (400, 413, 503), so that a browser
  // sees the problem instead of a network error. `origin` is empty when the head was not read that
  // far: then only a policy that allows any origin can say so ("*").
  [[nodiscard]] std::vector<ResponseHeader> rejection_headers(std::string_view origin) const;

  // An OPTIONS request to a known route, after decorate(): 204 with Allow, plus the rest of the
  // preflight answer when the Origin is allowed. `allow` is the route's method list.
  static void answer_options(HttpResponse& res, const std::string& allow);

 private:
  [[nodiscard]] bool allows(std::string_view origin) const;
  // Vary, and Allow-Origin with Expose-Headers when allowed. `origin_unread`: the request's Origin
  // is not known, so only an any-origin policy can allow it.
  [[nodiscard]] std::vector<ResponseHeader> headers_for(std::string_view origin,
                                                        bool origin_unread) const;

  std::vector<std::string> origins_;  // exact origins, or "*" for any
};

}  // namespace cutcalc::service
