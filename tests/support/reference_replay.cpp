#include "support/reference_replay.h"

#include <algorithm>
#include <cctype>

#include "support/project_contract.h"

namespace cutcalc::testing {
namespace {}  // namespace

std::vector<ReferenceCase> load_cases(const std::string& file_name) {
  std::vector<ReferenceCase> cases;
  const nlohmann::json document = load_reference(file_name);
  for (const auto& item : document.at("cases")) {
    cases.push_back({file_name, document.at("endpoint").get<std::string>(), item});
  }
  return cases;
}

std::string reference_case_name(const ::testing::TestParamInfo<ReferenceCase>& info) {
  std::string name = info.param.data.at("id").get<std::string>();
  std::replace_if(
      name.begin(), name.end(),
      [](char c) { return std::isalnum(static_cast<unsigned char>(c)) == 0; }, '_');
  return name;
}

ToleranceFn abs_rel_tolerance(const nlohmann::json& tolerance) {
  const double abs = tolerance.at("abs").get<double>();
  const double rel = tolerance.at("rel").get<double>();
  return [abs, rel](const std::string& /*key*/, double want) {
    return std::max(abs, rel * std::abs(want));
  };
}

JsonReply replay_reference_case(const ReferenceCase& reference, const ToleranceFn& tolerance) {
  const nlohmann::json& expect = reference.data.at("expect");
  const JsonReply reply = post(reference.endpoint, reference.data.at("request").dump());
  SCOPED_TRACE(reference.data.value("about", std::string()) + "\nresponse: " + reply.body);

  EXPECT_EQ(reply.status, expect.at("status").get<int>());
  if (reply.json.is_discarded()) {
    ADD_FAILURE() << "the response is not JSON";
    return reply;
  }
  if (reply.status == 200 && expect.contains("body")) {
    EXPECT_EQ(reply.content_type, "application/json");
    for (const std::string& mismatch : compare_subset(expect.at("body"), reply.json, tolerance)) {
      ADD_FAILURE() << mismatch;
    }
  } else if (expect.contains("pointer")) {
    EXPECT_EQ(reply.content_type, "application/problem+json");
    const auto pointer = expect.at("pointer").get<std::string>();
    EXPECT_TRUE(problem_names_pointer(reply.json, pointer))
        << "expected an error at pointer \"" << pointer << "\"";
  }
  for (const std::string& violation : test_support::project_contract().check_response(
           "post", reference.endpoint, reply.status, reply.content_type, reply.json)) {
    ADD_FAILURE() << "response breaks openapi.yaml: " << violation;
  }
  return reply;
}

}  // namespace cutcalc::testing
