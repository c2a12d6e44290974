#pragma once
// The cases of a shared/reference/*.json file, for tests that build on the reference requests.
// Replaying the cases themselves is tools/contract/replay.mjs's (ctest ReferenceReplay.*).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "support/test_server.h"

namespace cutcalc::testing {

struct ReferenceCase {
  std::string file;
  std::string endpoint;
  nlohmann::json data;  // id, about, request, expect, tolerance
};

inline std::vector<ReferenceCase> load_cases(const std::string& file_name) {
  std::vector<ReferenceCase> cases;
  const nlohmann::json document = load_reference(file_name);
  for (const auto& item : document.at("cases")) {
    cases.push_back({file_name, document.at("endpoint").get<std::string>(), item});
  }
  return cases;
}

}  // namespace cutcalc::testing
