#pragma once
// What an endpoint answers, independent of the HTTP library so that handlers are unit-testable.

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "domain/common/text_source.h"

namespace cutcalc::api {

struct ApiResponse {
  int status = 200;
  std::string content_type = "application/json";
  std::string body;
  std::vector<std::pair<std::string, std::string>> headers;  // extra response headers
  // A body written as it is sent (a program of many megabytes), instead of `body`.
  std::shared_ptr<domain::TextSource> body_source;
};

}  // namespace cutcalc::api
