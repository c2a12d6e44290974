#pragma once
// Facts fixed when the binary was built.

#include <string_view>

namespace cutcalc::service {

std::string_view build_version();          // project version, e.g. "0.1.0"
std::string_view build_commit();           // short git commit, or "unknown"
std::string_view build_type();             // CMAKE_BUILD_TYPE
std::string_view embedded_openapi_yaml();  // openapi.yaml as it was in the tree

}  // namespace cutcalc::service
