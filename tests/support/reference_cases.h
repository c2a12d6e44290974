#pragma once
// The cases of a shared/reference/*.json file, for tests that build on the reference requests.
// Replaying the cases themselves is tools/contract/replay.mjs's (ctest ReferenceReplay.*).

#include <algorithm>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "api/routes.h"
#include "support/test_server.h"

namespace cutcalc::testing {

struct ReferenceCase {
  std::string file;
  std::string endpoint;
  nlohmann::json data;  // id, about, request, expect, tolerance
};

// The cases of `file_name`, then those of the next/ files its route lists (api/routes.h: cases of
// the same endpoint that joined once the service answers them).
inline std::vector<ReferenceCase> load_cases(const std::string& file_name) {
  std::vector<std::string> files = {file_name};
  for (const api::CalculationRoute& route : api::calculation_routes()) {
    const auto listed = api::reference_files_of(route);
    if (std::find(listed.begin(), listed.end(), file_name) != listed.end()) {
      for (const std::string_view file : listed) {
        // A route with only a next/ file (grooving) lists `file_name` itself: once is enough.
        if (file.starts_with("next/") && file != file_name) files.emplace_back(file);
      }
    }
  }
  std::vector<ReferenceCase> cases;
  for (const std::string& file : files) {
    const nlohmann::json document = load_reference(file);
    for (const auto& item : document.at("cases")) {
      cases.push_back({file, document.at("endpoint").get<std::string>(), item});
    }
  }
  return cases;
}

}  // namespace cutcalc::testing
