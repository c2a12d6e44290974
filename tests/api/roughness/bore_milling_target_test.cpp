// /v1/roughness/bore-milling with `target_cusp_um` and `curve_points` (spec roughness.md B.9):
// the largest feed, the Delta(S) samples for the plot and their range, the 422s at
// /target_cusp_um, /curve_points and "", the default answer unchanged, and every answer within
// openapi.yaml.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "api/roughness/bore_milling_endpoint.h"
#include "support/project_contract.h"
#include "support/reference_compare.h"
#include "support/route_paths.h"
#include "support/sanity_checks.h"
#include "support/test_server.h"

namespace cutcalc::testing {
namespace {

using nlohmann::json;

// The paper's Table 1 setting (spec B.6) with the B.9 example's target 0.05 um.
json table1(bool target = true) {
  json request = {{"bore_radius_mm", 81.0},
                  {"cutter_radius_mm", 32.4},
                  {"teeth", 4},
                  {"feed_per_rev_mm", 0.2},
                  {"milling", "up"}};
  if (target) {
    request["target_cusp_um"] = 0.05;
  }
  return request;
}

json with(json request, const char* member, const json& value) {
  request[member] = value;
  return request;
}

TEST(BoreMillingTargetApi, LargestFeedReachesTheTarget) {
  const JsonReply reply = post_ok(kBoreMillingPath, table1());
  const double max_feed = reply.json.at("max_feed_per_rev_mm").get<double>();
  EXPECT_NEAR(max_feed, 0.353339, 5e-7);  // B.9 example
  const JsonReply at_max =
      post_ok(kBoreMillingPath, with(table1(false), "feed_per_rev_mm", max_feed));
  EXPECT_NEAR(at_max.json.at("cusp_height_um").get<double>(), 0.05, 1e-12 * 0.05);
  // It does not depend on the request's feed.
  EXPECT_EQ(post_ok(kBoreMillingPath, with(table1(), "feed_per_rev_mm", 3.0))
                .json.at("max_feed_per_rev_mm"),
            reply.json.at("max_feed_per_rev_mm"));
}

TEST(BoreMillingTargetApi, RestOfTheAnswerIsUnchanged) {
  const JsonReply plain = post_ok(kBoreMillingPath, table1(false));
  EXPECT_FALSE(plain.json.contains("max_feed_per_rev_mm"));
  EXPECT_FALSE(plain.json.contains("curve"));
  JsonReply with_target = post_ok(kBoreMillingPath, table1());
  with_target.json.erase("max_feed_per_rev_mm");
  EXPECT_EQ(with_target.json, plain.json);
  JsonReply with_curve = post_ok(kBoreMillingPath, with(table1(false), "curve_points", 10));
  ASSERT_TRUE(with_curve.json.contains("curve"));
  with_curve.json.erase("curve");
  EXPECT_EQ(with_curve.json, plain.json);
}

TEST(BoreMillingTargetApi, UnreachableTargetIsAProblemAtTheRoot) {
  // R 20, r 8, n 1, up: Delta(S_lim) = 5577.79 um.
  const json request = {
      {"bore_radius_mm", 20.0}, {"cutter_radius_mm", 8.0}, {"teeth", 1},
      {"feed_per_rev_mm", 2.0}, {"milling", "up"},         {"target_cusp_um", 6000.0}};
  const JsonReply reply = post(kBoreMillingPath, request.dump());
  ASSERT_EQ(reply.status, 422) << reply.body;
  EXPECT_EQ(reply.json.at("type"), "urn:cutcalc:problem:impossible-input");
  ASSERT_TRUE(problem_names_pointer(reply.json, "")) << reply.body;
  const json& error = reply.json.at("errors").at(0);
  EXPECT_EQ(error.at("code"), "target_cusp_unreachable");
  EXPECT_NEAR(error.at("maximum").get<double>(), 5577.79, 0.005);
  EXPECT_NE(error.at("detail").get<std::string>().find("5577.79"), std::string::npos)
      << error.dump();
  // With a curve too: the same problem.
  EXPECT_EQ(post(kBoreMillingPath, with(request, "curve_points", 5).dump()).status, 422);
  // Just below Delta(S_lim): answered.
  EXPECT_EQ(post(kBoreMillingPath, with(request, "target_cusp_um", 5577.0).dump()).status, 200);
}

TEST(BoreMillingCurveApi, CurveRunsToTheLargerMarginWithinTheModel) {
  // With the target: 1.25 S(T) = 0.4417 > 1.5 x 0.2.
  const JsonReply with_target = post_ok(kBoreMillingPath, with(table1(), "curve_points", 50));
  const json& curve = with_target.json.at("curve");
  ASSERT_EQ(curve.size(), 50u);
  const double max_feed = with_target.json.at("max_feed_per_rev_mm").get<double>();
  EXPECT_DOUBLE_EQ(curve.back().at("feed_per_rev_mm").get<double>(), 1.25 * max_feed);
  EXPECT_DOUBLE_EQ(curve.front().at("feed_per_rev_mm").get<double>(), 1.25 * max_feed / 50);
  // Without: 1.5 S.
  const JsonReply without = post_ok(kBoreMillingPath, with(table1(false), "curve_points", 2));
  ASSERT_EQ(without.json.at("curve").size(), 2u);
  EXPECT_DOUBLE_EQ(without.json.at("curve")[1].at("feed_per_rev_mm").get<double>(), 0.3);
  EXPECT_DOUBLE_EQ(without.json.at("curve")[0].at("feed_per_rev_mm").get<double>(), 0.15);
  // A feed near the model's limit: capped at S_lim, whose next double is refused.
  const json near_limit = {
      {"bore_radius_mm", 20.0},  {"cutter_radius_mm", 8.0}, {"teeth", 1},
      {"feed_per_rev_mm", 15.0}, {"milling", "up"},         {"curve_points", 3}};
  const JsonReply capped = post_ok(kBoreMillingPath, near_limit);
  const double S_lim = capped.json.at("curve")[2].at("feed_per_rev_mm").get<double>();
  EXPECT_LT(S_lim, 22.5);
  EXPECT_EQ(post_ok(kBoreMillingPath, with(near_limit, "feed_per_rev_mm", S_lim))
                .json.at("cusp_height_um"),
            capped.json.at("curve")[2].at("cusp_height_um"));
  const JsonReply beyond = post(
      kBoreMillingPath, with(near_limit, "feed_per_rev_mm", std::nextafter(S_lim, 1e9)).dump());
  EXPECT_EQ(beyond.status, 422) << beyond.body;
}

TEST(BoreMillingCurveApi, EachSampleIsTheAnswerForItsFeed) {
  const JsonReply reply = post_ok(kBoreMillingPath, with(table1(), "curve_points", 30));
  double previous = 0.0;
  for (const json& point : reply.json.at("curve")) {
    const double feed = point.at("feed_per_rev_mm").get<double>();
    const JsonReply single =
        post_ok(kBoreMillingPath, with(table1(false), "feed_per_rev_mm", feed));
    EXPECT_EQ(point.at("cusp_height_um"), single.json.at("cusp_height_um")) << feed;
    EXPECT_GT(point.at("cusp_height_um").get<double>(), previous);  // B11
    previous = point.at("cusp_height_um").get<double>();
  }
}

TEST(BoreMillingTargetApi, OutOfRangeOrWrongTypeNamesTheField) {
  const std::pair<const char*, std::vector<json>> fields[] = {
      {"curve_points",
       {json(1), json(0), json(-2), json(1001), json(1e12), json(10.5), json("10"), json(false),
        json(nullptr), json::array({10})}},
      {"target_cusp_um",
       {json(0), json(-1), json(1.000001e9), json("0.05"), json(true), json(nullptr),
        json::array({0.05})}}};
  for (const auto& [member, values] : fields) {
    const std::string pointer = std::string("/") + member;
    for (const json& bad : values) {
      SCOPED_TRACE(pointer + " = " + bad.dump());
      const json request = with(table1(), member, bad);
      const JsonReply reply = post(kBoreMillingPath, request.dump());
      EXPECT_EQ(reply.status, 422) << reply.body;
      EXPECT_TRUE(problem_names_pointer(reply.json, pointer)) << reply.body;
      EXPECT_EQ(expect_sane_answer(kBoreMillingPath, &api::roughness::handle_bore_milling, request),
                422);
      const auto v =
          test_support::project_contract().check_request("POST", kBoreMillingPath, request);
      EXPECT_TRUE(std::any_of(v.begin(), v.end(), [&](const std::string& violation) {
        return violation.rfind("at \"" + pointer + "\"", 0) == 0;
      }));
    }
  }
  EXPECT_EQ(post_ok(kBoreMillingPath, with(table1(), "curve_points", 1000)).json.at("curve").size(),
            1000u);
  EXPECT_EQ(post_ok(kBoreMillingPath, with(table1(), "curve_points", 2.0)).json.at("curve").size(),
            2u);
}

TEST(BoreMillingCurveApi, ExtremeRequestsAnswerSanely) {
  for (const double R : {1e-6 * 2, 20.0, 1e6}) {
    for (const double ratio : {1e-3, 0.4, 0.999999}) {
      for (const double feed : {1e-6, 1.0, 1e6}) {
        for (const char* milling : {"up", "down"}) {
          json request = {{"bore_radius_mm", R},
                          {"cutter_radius_mm", R * ratio},
                          {"teeth", 3},
                          {"feed_per_rev_mm", feed},
                          {"milling", milling},
                          {"curve_points", 20},
                          {"target_cusp_um", 1e-6}};
          EXPECT_NE(
              expect_sane_answer(kBoreMillingPath, &api::roughness::handle_bore_milling, request),
              0);
          request["target_cusp_um"] = 1e9;
          EXPECT_NE(
              expect_sane_answer(kBoreMillingPath, &api::roughness::handle_bore_milling, request),
              0);
        }
      }
    }
  }
}

}  // namespace
}  // namespace cutcalc::testing
