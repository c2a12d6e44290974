// An error's pointer names the member whose value breaks the rule, also when that member is absent
// and its default or implied value is at fault (openapi.yaml, ProblemFieldError.pointer): the
// pointer says which value to change, whether or not the request gave it.

#include <gtest/gtest.h>

#include <string>

#include "support/project_contract.h"
#include "support/test_server.h"

namespace cutcalc::testing {
namespace {

using nlohmann::json;

json main_time_request() {
  return json::parse(R"({
    "cutter_diameter_mm": 50, "teeth": 4, "spindle_speed_rpm": 1000, "feed_per_tooth_mm": 0.1,
    "length_mm": 120,
    "entry": {"contour": "straight", "width_mm": 80},
    "exit": {"contour": "straight", "width_mm": 80},
    "allowance": {"width_mm": 80, "width_of_cut_mm": 45, "depth_mm": 5, "depth_of_cut_mm": 2}})");
}

void expect_single_error(const JsonReply& reply, const std::string& pointer,
                         const std::string& code) {
  ASSERT_EQ(reply.status, 422) << reply.body;
  ASSERT_EQ(reply.json.at("errors").size(), 1U) << reply.body;
  EXPECT_EQ(reply.json.at("errors")[0].at("pointer"), pointer) << reply.body;
  EXPECT_EQ(reply.json.at("errors")[0].at("code"), code) << reply.body;
}

// A convex exit arc without width_mm spans 2 radius_mm (E3): that implied width is at fault.
TEST(AbsentMemberPointer, ExitArcWithoutWidthPointsAtItsImpliedWidth) {
  json request = main_time_request();
  request["exit"] = {{"contour", "convex_arc"}, {"radius_mm", 50}};
  const JsonReply reply = post("/v1/main-time", request.dump());
  expect_single_error(reply, "/exit/width_mm", "exit_width_mismatch");
  EXPECT_FALSE(request["exit"].contains("width_mm"));
}

// clearance_mm defaults to 2 mm: with safe_z_mm 1 the default is above it.
TEST(AbsentMemberPointer, DefaultClearanceAboveSafeHeightPointsAtTheClearance) {
  json request = main_time_request();
  request["program"] = {{"safe_z_mm", 1}};
  const JsonReply reply = post("/v1/main-time/program", request.dump());
  expect_single_error(reply, "/program/clearance_mm", "not_above");
  EXPECT_EQ(reply.json.at("errors")[0].at("field"), "safe_z_mm");
}

TEST(AbsentMemberPointer, TheContractSaysAPointerMayNameAnAbsentMember) {
  const json document = test_support::project_contract().document();
  const json& pointer = document.at("components")
                            .at("schemas")
                            .at("ProblemFieldError")
                            .at("properties")
                            .at("pointer");
  const std::string description = pointer.at("description").get<std::string>();
  EXPECT_NE(description.find("absent"), std::string::npos) << description;
  EXPECT_NE(description.find("default"), std::string::npos) << description;
  EXPECT_NE(description.find("implied"), std::string::npos) << description;
}

}  // namespace
}  // namespace cutcalc::testing
