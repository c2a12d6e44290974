#pragma once
// Replaying shared/reference/*.json over HTTP: load the cases, post each request to the real
// server, and check status, values, error pointers and the openapi.yaml contract.

#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "support/reference_compare.h"
#include "support/test_server.h"

namespace cutcalc::testing {

struct ReferenceCase {
  std::string file;
  std::string endpoint;
  nlohmann::json data;  // id, about, request, expect, tolerance
};

std::vector<ReferenceCase> load_cases(const std::string& file_name);

// gtest prints a failing parameter with this: the case id, not the object's bytes.
inline void PrintTo(const ReferenceCase& reference, std::ostream* out) {
  *out << reference.file << ":" << reference.data.value("id", std::string("?"));
}

// gtest parameter name: the case id with non-alphanumerics replaced.
std::string reference_case_name(const ::testing::TestParamInfo<ReferenceCase>& info);

// Rule of the files with {"abs", "rel"} tolerances: |got - want| <= max(abs, rel |want|).
ToleranceFn abs_rel_tolerance(const nlohmann::json& tolerance);

// Posts the case's request and checks the reply (ADD_FAILURE on every mismatch); returns it.
JsonReply replay_reference_case(const ReferenceCase& reference, const ToleranceFn& tolerance);

}  // namespace cutcalc::testing
