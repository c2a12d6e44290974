// The polygon-hole answer forms over HTTP. The cases of shared/reference/polygon-hole.json (values,
// bounds, warning codes, program facts) are replayed by tools/contract/replay.mjs (ctest
// ReferenceReplay.EveryCaseOverHttp).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <set>
#include <sstream>

#include "support/reference_cases.h"

namespace cutcalc::testing {
namespace {

using nlohmann::json;

TEST(PolygonHoleHttp, AcceptTextPlainAnswersTheBareProgramAsAnAttachment) {
  auto client = TestServer::shared().client();
  const auto reply = client->Post(
      "/v1/polygon-hole/gcode", {{"Accept", "text/plain"}},
      R"({"faces": 4, "inscribed_diameter_mm": 16, "depth_mm": 0.1, "step_down_mm": 0.1,
          "spindle_speed_rpm": 30})",
      "application/json");
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->status, 200);
  EXPECT_EQ(reply->get_header_value("Content-Type"), "text/plain; charset=us-ascii");
  EXPECT_EQ(reply->get_header_value("Content-Disposition"),
            "attachment; filename=\"polygon-hole-N4-d16.0000.ngc\"");
  EXPECT_EQ(reply->body.rfind("%\n(CUTCALC POLYGON HOLE N4 D16.0000 A16.0000)", 0), 0U)
      << reply->body.substr(0, 200);
  EXPECT_NE(reply->body.find("(WARNING phase_not_locked: "), std::string::npos);
  EXPECT_EQ(reply->body.back(), '\n');
}

TEST(PolygonHoleHttp, ErrorsStayProblemJsonWhateverTheAcceptHeader) {
  auto client = TestServer::shared().client();
  const auto reply = client->Post("/v1/polygon-hole/gcode", {{"Accept", "text/plain"}},
                                  R"({"faces": 13})", "application/json");
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->status, 422);
  EXPECT_EQ(reply->get_header_value("Content-Type"), "application/problem+json");
}

}  // namespace
}  // namespace cutcalc::testing
