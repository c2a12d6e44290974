// /v1/roughness/groove-wall, addition R.7 (roughness.md R9-R14): `ra_um` in every answer,
// `bearing_curve` exactly with `bearing_points`, field errors at /bearing_points, the rest of the
// answer unchanged, and every answer within openapi.yaml.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "api/roughness/groove_wall_endpoint.h"
#include "support/project_contract.h"
#include "support/reference_compare.h"
#include "support/route_paths.h"
#include "support/sanity_checks.h"
#include "support/test_server.h"

namespace cutcalc::testing {
namespace {

using nlohmann::json;

// The spec's worked_ra geometry (R.5): rho 0.3 mm, phi1 2 deg, pitch S0 = 0.12 mm.
json worked_ra() {
  return {{"feed_mm", 0.12}, {"nose_radius_mm", 0.3}, {"minor_edge_angle_deg", 2}};
}

json with_bearing(json request, const json& points) {
  request["bearing_points"] = points;
  return request;
}

TEST(GrooveWallRaApi, EveryAnswerHasRa) {
  // R.7 facts: S 0.12 -> Ra 0.70803 um; with a target or a curve Ra is the same.
  const JsonReply plain = post_ok(kGrooveWallPath, worked_ra());
  EXPECT_NEAR(plain.json.at("ra_um").get<double>(), 0.70803, 0.5e-5);
  json with_target = worked_ra();
  with_target["target_rz_um"] = 13.2;
  with_target["curve_points"] = 5;
  EXPECT_EQ(post_ok(kGrooveWallPath, with_target).json.at("ra_um"), plain.json.at("ra_um"));
  // phi1 = 0: a flat wall.
  json flat = worked_ra();
  flat["minor_edge_angle_deg"] = 0;
  EXPECT_EQ(post_ok(kGrooveWallPath, flat).json.at("ra_um").get<double>(), 0.0);
}

TEST(GrooveWallRaApi, BearingCurveOnlyWhenAskedAndTheRestUnchanged) {
  const JsonReply plain = post_ok(kGrooveWallPath, worked_ra());
  EXPECT_FALSE(plain.json.contains("bearing_curve"));
  // 5.0 is an integer-valued number: accepted like 5.
  for (const json& points : {json(5), json(5.0)}) {
    JsonReply with_curve = post_ok(kGrooveWallPath, with_bearing(worked_ra(), points));
    const json& curve = with_curve.json.at("bearing_curve");
    ASSERT_EQ(curve.size(), 5u);
    const double rz = with_curve.json.at("rz_um").get<double>();
    EXPECT_DOUBLE_EQ(curve[0].at("depth_um").get<double>(), rz / 5);
    EXPECT_EQ(curve[4].at("depth_um").get<double>(), rz);
    EXPECT_EQ(curve[4].at("material_ratio").get<double>(), 1.0);
    with_curve.json.erase("bearing_curve");
    EXPECT_EQ(with_curve.json, plain.json);
  }
  EXPECT_EQ(
      post_ok(kGrooveWallPath, with_bearing(worked_ra(), 1000)).json.at("bearing_curve").size(),
      1000u);
}

TEST(GrooveWallRaApi, OutOfRangeOrWrongTypeNamesTheField) {
  for (const json& bad : {json(1), json(0), json(-2), json(1001), json(1e12), json(2.5), json("10"),
                          json(false), json(nullptr), json::array({10})}) {
    SCOPED_TRACE(bad.dump());
    const JsonReply reply = post(kGrooveWallPath, with_bearing(worked_ra(), bad).dump());
    EXPECT_EQ(reply.status, 422) << reply.body;
    EXPECT_TRUE(problem_names_pointer(reply.json, "/bearing_points")) << reply.body;
    EXPECT_EQ(expect_sane_answer(kGrooveWallPath, &api::roughness::handle_groove_wall,
                                 with_bearing(worked_ra(), bad)),
              422);
    const auto v = test_support::project_contract().check_request("POST", kGrooveWallPath,
                                                                  with_bearing(worked_ra(), bad));
    EXPECT_TRUE(std::any_of(v.begin(), v.end(), [](const std::string& violation) {
      return violation.rfind("at \"/bearing_points\"", 0) == 0;
    }));
  }
}

TEST(GrooveWallRaApi, ModelErrorsStayTheRequestsErrors) {
  // A target with phi1 = 0: the same 422 at "" with a bearing curve asked for.
  json request = with_bearing(worked_ra(), 4);
  request["minor_edge_angle_deg"] = 0;
  request["target_rz_um"] = 5.0;
  const JsonReply reply = post(kGrooveWallPath, request.dump());
  EXPECT_EQ(reply.status, 422);
  EXPECT_TRUE(problem_names_pointer(reply.json, "")) << reply.body;
}

TEST(GrooveWallRaApi, ExtremeRequestsAnswerSanely) {
  for (const double feed : {1e-6, 0.5, 1e6}) {
    for (const double rho : {1e-6, 0.3, 1e6}) {
      for (const double phi1 : {0.0, 1e-300, 1e-9, 2.0, 45.0, 89.999999}) {
        const json request = {{"feed_mm", feed},
                              {"nose_radius_mm", rho},
                              {"minor_edge_angle_deg", phi1},
                              {"bearing_points", 50}};
        SCOPED_TRACE(request.dump());
        EXPECT_EQ(expect_sane_answer(kGrooveWallPath, &api::roughness::handle_groove_wall, request),
                  200);
      }
    }
  }
}

}  // namespace
}  // namespace cutcalc::testing
