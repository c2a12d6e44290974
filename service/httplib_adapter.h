#pragma once
// What the service still takes from cpp-httplib (the project's HTTP library: also the tests' and
// the benchmarks' client). The engine parses and answers requests itself (one parse per request,
// service/http_request.h); the library's URL decoding is reused here, and only here, so that a
// path means what it meant when the library routed requests.

#include <string>
#include <string_view>

namespace cutcalc::service {

// `path` with its %XX escapes decoded ('+' stays '+': it is not a space in a path).
std::string percent_decode_path(std::string_view path);

}  // namespace cutcalc::service
