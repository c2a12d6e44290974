#include "support/project_contract.h"

#include <gtest/gtest.h>

namespace cutcalc::test_support {

const OpenApiContract& project_contract() {
  // Every schema is compiled by ContractCheck.EveryLoggedAnswerMatchesOpenApi in the same ctest
  // run; a test process compiles those its checks use (test start-up time).
  static const OpenApiContract loaded =
      OpenApiContract::load(CUTCALC_OPENAPI_PATH, OpenApiContract::Compile::when_used);
  return loaded;
}

}  // namespace cutcalc::test_support

namespace cutcalc::testing {

JsonReply post_ok(const std::string& path, const nlohmann::json& request) {
  const JsonReply reply = post(path, request.dump());
  EXPECT_EQ(reply.status, 200) << reply.body.substr(0, 400);
  return reply;
}

void expect_conforms(const std::string& path, const JsonReply& reply) {
  for (const auto& violation : test_support::project_contract().check_response(
           "post", path, reply.status, reply.content_type, reply.json)) {
    ADD_FAILURE() << "response breaks openapi.yaml: " << violation
                  << "\nresponse: " << reply.body.substr(0, 400);
  }
}

}  // namespace cutcalc::testing
