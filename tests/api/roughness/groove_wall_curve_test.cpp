// /v1/roughness/groove-wall with `curve_points`: the Rz(S) samples for the plot, their range,
// field errors at /curve_points, the default answer unchanged, and every answer within
// openapi.yaml.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
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

// gw-target-paper-13.2: the spec's worked example R.5 with the paper's measured 13.2 um.
json worked(bool target = true) {
  json request = {{"feed_mm", 0.12}, {"nose_radius_mm", 0.3}, {"minor_edge_angle_deg", 2}};
  if (target) {
    request["target_rz_um"] = 13.2;
  }
  return request;
}

json with_points(json request, const json& points) {
  request["curve_points"] = points;
  return request;
}

TEST(GrooveWallCurveApi, CurveRunsToTheLargerOfBothMargins) {
  // With the target: S(T) = 0.471245 mm, 1.25 S(T) > 1.5 x 0.12.
  const JsonReply with_target = post_ok(kGrooveWallPath, with_points(worked(), 50));
  const json& curve = with_target.json.at("curve");
  ASSERT_EQ(curve.size(), 50u);
  const double max_feed = with_target.json.at("max_feed_mm").get<double>();
  EXPECT_DOUBLE_EQ(curve.back().at("feed_mm").get<double>(), 1.25 * max_feed);
  EXPECT_DOUBLE_EQ(curve.front().at("feed_mm").get<double>(), 1.25 * max_feed / 50);
  // Without: 1.5 S.
  const JsonReply without = post_ok(kGrooveWallPath, with_points(worked(false), 2));
  ASSERT_EQ(without.json.at("curve").size(), 2u);
  EXPECT_DOUBLE_EQ(without.json.at("curve")[1].at("feed_mm").get<double>(), 1.5 * 0.12);
  EXPECT_DOUBLE_EQ(without.json.at("curve")[0].at("feed_mm").get<double>(), 0.75 * 0.12);
  EXPECT_FALSE(without.json.contains("max_feed_mm"));
}

TEST(GrooveWallCurveApi, EachSampleIsTheAnswerForItsFeed) {
  const JsonReply reply = post_ok(kGrooveWallPath, with_points(worked(), 40));
  double previous = 0.0;
  for (const json& point : reply.json.at("curve")) {
    const double feed = point.at("feed_mm").get<double>();
    const JsonReply single = post_ok(
        kGrooveWallPath, {{"feed_mm", feed}, {"nose_radius_mm", 0.3}, {"minor_edge_angle_deg", 2}});
    EXPECT_EQ(point.at("rz_um"), single.json.at("rz_um")) << feed;
    EXPECT_EQ(point.at("branch"), single.json.at("branch")) << feed;
    EXPECT_GT(point.at("rz_um").get<double>(), previous);  // R7: Rz rises with the feed
    previous = point.at("rz_um").get<double>();
  }
}

TEST(GrooveWallCurveApi, RestOfTheAnswerIsUnchanged) {
  for (const bool target : {false, true}) {
    const JsonReply plain = post_ok(kGrooveWallPath, worked(target));
    EXPECT_FALSE(plain.json.contains("curve"));
    JsonReply with_curve = post_ok(kGrooveWallPath, with_points(worked(target), 10));
    ASSERT_TRUE(with_curve.json.contains("curve"));
    with_curve.json.erase("curve");
    EXPECT_EQ(with_curve.json, plain.json);
  }
}

TEST(GrooveWallCurveApi, OutOfRangeOrWrongTypeNamesTheField) {
  for (const json& bad : {json(1), json(0), json(-2), json(1001), json(1e12), json(10.5),
                          json("10"), json(false), json(nullptr), json::array({10})}) {
    SCOPED_TRACE(bad.dump());
    const JsonReply reply = post(kGrooveWallPath, with_points(worked(), bad).dump());
    EXPECT_EQ(reply.status, 422) << reply.body;
    EXPECT_TRUE(problem_names_pointer(reply.json, "/curve_points")) << reply.body;
    EXPECT_EQ(expect_sane_answer(kGrooveWallPath, &api::roughness::handle_groove_wall,
                                 with_points(worked(), bad)),
              422);
    const auto v = test_support::project_contract().check_request("POST", kGrooveWallPath,
                                                                  with_points(worked(), bad));
    EXPECT_TRUE(std::any_of(v.begin(), v.end(), [](const std::string& violation) {
      return violation.rfind("at \"/curve_points\"", 0) == 0;
    }));
  }
  EXPECT_TRUE(test_support::project_contract()
                  .check_request("POST", kGrooveWallPath, with_points(worked(), 1000))
                  .empty());
  EXPECT_EQ(post_ok(kGrooveWallPath, with_points(worked(), 1000)).json.at("curve").size(), 1000u);
}

TEST(GrooveWallCurveApi, ModelErrorsStayTheRequestsErrors) {
  // gw-err-target-with-phi1-0 with a curve: the same 422 at "".
  json request = with_points(worked(), 10);
  request["minor_edge_angle_deg"] = 0;
  const JsonReply reply = post(kGrooveWallPath, request.dump());
  EXPECT_EQ(reply.status, 422);
  EXPECT_TRUE(problem_names_pointer(reply.json, "")) << reply.body;
  // phi1 = 0 without a target: a flat curve of zeros.
  request.erase("target_rz_um");
  const JsonReply flat = post_ok(kGrooveWallPath, request);
  for (const json& point : flat.json.at("curve")) {
    EXPECT_EQ(point.at("rz_um").get<double>(), 0.0);
    EXPECT_EQ(point.at("branch"), "nose_arc_and_minor_edge");
  }
  // S(T) finite but 1.25 S(T) beyond a double: 422 at "", never a 500 or an infinity.
  json vanishing = with_points(worked(), 10);
  vanishing["minor_edge_angle_deg"] = 3.5e-301;
  vanishing["target_rz_um"] = 1e9;
  EXPECT_EQ(expect_sane_answer(kGrooveWallPath, &api::roughness::handle_groove_wall, vanishing),
            422);
}

TEST(GrooveWallCurveApi, ExtremeRequestsAnswerSanely) {
  for (const double feed : {1e-6, 0.5, 1e6}) {
    for (const double rho : {1e-6, 0.3, 1e6}) {
      for (const double phi1 : {0.0, 1e-9, 2.0, 45.0, 89.999999}) {
        json request = {{"feed_mm", feed},
                        {"nose_radius_mm", rho},
                        {"minor_edge_angle_deg", phi1},
                        {"curve_points", 50}};
        if (phi1 > 0.0) {
          request["target_rz_um"] = 1e9;
        }
        EXPECT_NE(expect_sane_answer(kGrooveWallPath, &api::roughness::handle_groove_wall, request),
                  0);
      }
    }
  }
}

}  // namespace
}  // namespace cutcalc::testing
