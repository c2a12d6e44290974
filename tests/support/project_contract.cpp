#include "support/project_contract.h"

#include <gtest/gtest.h>

namespace cutcalc::test_support {

const OpenApiContract& project_contract() {
  static const OpenApiContract loaded = OpenApiContract::load(CUTCALC_OPENAPI_PATH);
  return loaded;
}

}  // namespace cutcalc::test_support

namespace cutcalc::testing {

JsonReply post_ok(const std::string& path, const nlohmann::json& request) {
  const JsonReply reply = post(path, request.dump());
  EXPECT_EQ(reply.status, 200) << reply.body.substr(0, 400);
  for (const std::string& violation : test_support::project_contract().check_response(
           "post", path, reply.status, reply.content_type, reply.json)) {
    ADD_FAILURE() << "response breaks openapi.yaml: " << violation;
  }
  return reply;
}

}  // namespace cutcalc::testing
