// Replays every case of shared/reference/entry-length.json and main-time.json over HTTP against
// the real server: status, values within the file's tolerances, error pointers, and the contract.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/openapi_contract.h"
#include "support/reference_compare.h"
#include "support/test_server.h"

namespace cutcalc::testing {
namespace {

struct ReferenceCase {
  std::string file;
  std::string endpoint;
  nlohmann::json data;
};

std::vector<ReferenceCase> load_cases(const std::string& file) {
  std::vector<ReferenceCase> cases;
  const nlohmann::json document = load_reference(file);
  for (const auto& item : document.at("cases")) {
    cases.push_back({file, document.at("endpoint").get<std::string>(), item});
  }
  return cases;
}

using test_support::OpenApiContract;

const OpenApiContract& contract() {
  static const OpenApiContract loaded = OpenApiContract::load(CUTCALC_OPENAPI_PATH);
  return loaded;
}

class EntryReferenceCase : public ::testing::TestWithParam<ReferenceCase> {};

TEST_P(EntryReferenceCase, ServiceAnswersAsTheReference) {
  const ReferenceCase& reference = GetParam();
  const nlohmann::json& expect = reference.data.at("expect");
  const JsonReply reply = post(reference.endpoint, reference.data.at("request").dump());
  SCOPED_TRACE(reference.data.value("about", std::string()) + "\nresponse: " + reply.body);

  ASSERT_EQ(reply.status, expect.at("status").get<int>());
  ASSERT_FALSE(reply.json.is_discarded());
  if (reply.status == 200) {
    EXPECT_EQ(reply.content_type, "application/json");
    const auto mismatches = compare_subset(expect.at("body"), reply.json,
                                           entry_file_tolerance(reference.data.at("tolerance")));
    for (const std::string& mismatch : mismatches) {
      ADD_FAILURE() << mismatch;
    }
  } else {
    EXPECT_EQ(reply.content_type, "application/problem+json");
    EXPECT_TRUE(problem_names_pointer(reply.json, expect.at("pointer").get<std::string>()))
        << "expected an error at pointer \"" << expect.at("pointer").get<std::string>() << "\"";
  }
  for (const std::string& violation : contract().check_response(
           "post", reference.endpoint, reply.status, reply.content_type, reply.json)) {
    ADD_FAILURE() << "response breaks openapi.yaml: " << violation;
  }
}

std::string case_name(const ::testing::TestParamInfo<ReferenceCase>& info) {
  std::string name = info.param.data.at("id").get<std::string>();
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) {
      c = '_';
    }
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(EntryLength, EntryReferenceCase,
                         ::testing::ValuesIn(load_cases("entry-length.json")), case_name);
INSTANTIATE_TEST_SUITE_P(MainTime, EntryReferenceCase,
                         ::testing::ValuesIn(load_cases("main-time.json")), case_name);

TEST(EntryReferenceFiles, HoldTheExpectedNumberOfCases) {
  // The spec announces 20 and 13 public cases; fewer would mean a truncated or moved file.
  EXPECT_GE(load_cases("entry-length.json").size(), 20U);
  EXPECT_GE(load_cases("main-time.json").size(), 13U);
}

}  // namespace
}  // namespace cutcalc::testing
