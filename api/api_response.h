#pragma once
// What an endpoint answers, independent of the HTTP library so that handlers are unit-testable.

#include <string>
#include <utility>
#include <vector>

namespace cutcalc::api {

struct ApiResponse {
  int status = 200;
  std::string content_type = "application/json";
  std::string body;
  std::vector<std::pair<std::string, std::string>> headers;  // extra response headers
};

}  // namespace cutcalc::api
