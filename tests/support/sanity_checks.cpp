#include "support/sanity_checks.h"

#include <gtest/gtest.h>

#include "support/project_contract.h"
#include "support/quantity_keys.h"

namespace cutcalc::testing {
namespace {

void expect_no_negative_lengths(const nlohmann::json& value, const std::string& key,
                                const std::string& request) {
  if (value.is_number()) {
    if (test_support::is_non_negative_quantity(key)) {
      EXPECT_GE(value.get<double>(), 0.0) << key << " for " << request;
    }
  } else if (value.is_object()) {
    for (const auto& [name, element] : value.items()) {
      expect_no_negative_lengths(element, name, request);
    }
  } else if (value.is_array()) {
    for (const auto& element : value) {
      expect_no_negative_lengths(element, key, request);
    }
  }
}

}  // namespace

int expect_sane_answer(const char* path, api::JsonHandler handler, const nlohmann::json& request) {
  const std::string body = request.dump();
  api::ApiResponse response =
      api::run_json_endpoint({path, "application/json", body, "sanity", ""}, handler);
  api::write_whole(response);
  EXPECT_TRUE(response.status == 200 || response.status == 422)
      << response.status << " for " << body << "\n"
      << response.body;
  const nlohmann::json parsed = nlohmann::json::parse(response.body, nullptr, false);
  if (parsed.is_discarded()) {
    ADD_FAILURE() << "not JSON: " << response.body;
    return 0;
  }
  EXPECT_TRUE(api::all_numbers_finite(parsed)) << body;
  if (response.status == 200) {
    expect_no_negative_lengths(parsed, "", body);
  }
  for (const std::string& violation : test_support::project_contract().check_response(
           "post", path, response.status, response.content_type, parsed)) {
    ADD_FAILURE() << violation << "\nrequest: " << body << "\nresponse: " << response.body;
  }
  return response.status;
}

}  // namespace cutcalc::testing
