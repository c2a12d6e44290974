// /v1/resultant-speeds with `arc_samples`: points evenly spaced over the engagement arc, the same
// values as the explicit angles, field errors at /arc_samples, both lists at "", the default
// answer unchanged, and every answer within openapi.yaml.

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <string>

#include "api/kinematics/resultant_speeds_endpoint.h"
#include "support/project_contract.h"
#include "support/reference_compare.h"
#include "support/route_paths.h"
#include "support/sanity_checks.h"
#include "support/test_server.h"

namespace cutcalc::testing {
namespace {

using nlohmann::json;

// rs-sample-up (spec resultant-speeds.md section 6).
json sample(const char* milling = "up") {
  return {{"tool_radius_mm", 10},       {"workpiece_radius_mm", 16}, {"flat_depth_mm", 1},
          {"tool_speed_rpm", 3000},     {"workpiece_speed_rpm", 10}, {"milling", milling},
          {"tool_feed_mm_per_min", 100}};
}

json with_samples(json request, const json& count) {
  request["arc_samples"] = count;
  return request;
}

TEST(ResultantSpeedsArcSamplesApi, PointsRunFromEntryToExitEvenlySpaced) {
  for (const char* milling : {"up", "down"}) {
    const JsonReply defaults = post_ok(kResultantSpeedsPath, sample(milling));
    for (const int count : {2, 3, 90, 361}) {
      SCOPED_TRACE(::testing::Message() << milling << " " << count);
      const JsonReply reply = post_ok(kResultantSpeedsPath, with_samples(sample(milling), count));
      const json& points = reply.json.at("points");
      ASSERT_EQ(points.size(), static_cast<std::size_t>(count));
      const double rho_e = reply.json.at("engagement_half_angle_deg").get<double>();
      EXPECT_EQ(rho_e, defaults.json.at("engagement_half_angle_deg").get<double>());
      // The ends are the default entry and exit points, every field.
      EXPECT_EQ(points.front(), defaults.json.at("points").front());
      EXPECT_EQ(points.back(), defaults.json.at("points").back());
      for (std::size_t i = 1; i < points.size(); ++i) {
        const double step = points[i - 1].at("contact_angle_deg").get<double>() -
                            points[i].at("contact_angle_deg").get<double>();
        EXPECT_NEAR(step, 2.0 * rho_e / (count - 1), 1e-12 * rho_e) << i;
      }
    }
  }
}

TEST(ResultantSpeedsArcSamplesApi, ValuesEqualTheSameExplicitAngles) {
  const JsonReply sampled = post_ok(kResultantSpeedsPath, with_samples(sample("down"), 25));
  json angles = json::array();
  for (const json& point : sampled.json.at("points")) {
    angles.push_back(point.at("contact_angle_deg"));
  }
  json request = sample("down");
  request["contact_angles_deg"] = angles;
  const JsonReply explicit_angles = post_ok(kResultantSpeedsPath, request);
  EXPECT_EQ(sampled.json, explicit_angles.json);
  // Through the JSON text and back, the angles are the same doubles.
  EXPECT_EQ(sampled.body, explicit_angles.body);
}

TEST(ResultantSpeedsArcSamplesApi, DefaultAnswerIsUnchanged) {
  // rs-sample-up, byte for byte as the openapi.yaml example that predates arc_samples.
  const JsonReply reply = post_ok(kResultantSpeedsPath, sample("up"));
  ASSERT_EQ(reply.json.at("points").size(), 3u);
  const json example =
      test_support::project_contract()
          .document()["paths"][kResultantSpeedsPath]["post"]["responses"]["200"]["content"]
                     ["application/json"]["examples"]["sampleUp"]["value"];
  EXPECT_TRUE(compare_subset(example, reply.json, [](const std::string&, double want) {
                return 1e-12 * std::abs(want);
              }).empty());
}

TEST(ResultantSpeedsArcSamplesApi, OutOfRangeOrWrongTypeNamesTheField) {
  for (const json& bad : {json(1), json(0), json(-3), json(362), json(1000000), json(2.5),
                          json("5"), json(true), json(nullptr), json::array({5}), json::object()}) {
    SCOPED_TRACE(bad.dump());
    const JsonReply reply = post(kResultantSpeedsPath, with_samples(sample(), bad).dump());
    EXPECT_EQ(reply.status, 422) << reply.body;
    EXPECT_EQ(reply.content_type, "application/problem+json");
    EXPECT_TRUE(problem_names_pointer(reply.json, "/arc_samples")) << reply.body;
    EXPECT_EQ(expect_sane_answer(kResultantSpeedsPath, &api::kinematics::handle_resultant_speeds,
                                 with_samples(sample(), bad)),
              422);
  }
  // 2.0 is the integer 2 (as faces 4.0 is 4).
  EXPECT_EQ(post_ok(kResultantSpeedsPath, with_samples(sample(), 2.0)).json.at("points").size(),
            2u);
}

TEST(ResultantSpeedsArcSamplesApi, BothAnglesAndSamplesAreACombinationError) {
  json both = with_samples(sample(), 5);
  both["contact_angles_deg"] = json::array({0});
  const JsonReply reply = post(kResultantSpeedsPath, both.dump());
  EXPECT_EQ(reply.status, 422) << reply.body;
  EXPECT_EQ(reply.json.value("type", ""), "urn:cutcalc:problem:invalid-input");
  EXPECT_TRUE(problem_names_pointer(reply.json, "")) << reply.body;
  EXPECT_FALSE(problem_names_pointer(reply.json, "/arc_samples")) << reply.body;
  EXPECT_EQ(
      expect_sane_answer(kResultantSpeedsPath, &api::kinematics::handle_resultant_speeds, both),
      422);
  // A field error in one of them is reported at the field (field checks come first).
  json bad_field = both;
  bad_field["arc_samples"] = 1;
  const JsonReply field = post(kResultantSpeedsPath, bad_field.dump());
  EXPECT_TRUE(problem_names_pointer(field.json, "/arc_samples")) << field.body;
}

TEST(ResultantSpeedsArcSamplesApi, RequestSchemaStatesTheRules) {
  EXPECT_TRUE(test_support::project_contract()
                  .check_request("POST", kResultantSpeedsPath, with_samples(sample(), 361))
                  .empty());
  for (const json& bad : {json(1), json(362), json(2.5), json("5")}) {
    const auto v = test_support::project_contract().check_request("POST", kResultantSpeedsPath,
                                                                  with_samples(sample(), bad));
    bool names = false;
    for (const std::string& violation : v) {
      names = names || violation.rfind("at \"/arc_samples\"", 0) == 0;
    }
    EXPECT_TRUE(names) << bad.dump();
  }
  json both = with_samples(sample(), 5);
  both["contact_angles_deg"] = json::array({0});
  const auto v = test_support::project_contract().check_request("POST", kResultantSpeedsPath, both);
  bool root = false;
  for (const std::string& violation : v) {
    root = root || violation.rfind("at \"\"", 0) == 0;
  }
  EXPECT_TRUE(root) << v.size();
}

TEST(ResultantSpeedsArcSamplesApi, DeepAndExtremeArcsAnswerSanely) {
  // rs-deep-flip-default (rho_e > 90 deg), a nearly tangent contact and a deep overlap.
  json deep = sample("down");
  deep["tool_radius_mm"] = 8;
  deep["workpiece_radius_mm"] = 20;
  deep["flat_depth_mm"] = 10;
  json tangent = sample();
  tangent.erase("flat_depth_mm");
  tangent["center_distance_mm"] = 25.999999999;
  json inside = sample();
  inside.erase("flat_depth_mm");
  inside["center_distance_mm"] = 6.000000001;
  for (const json& request : {deep, tangent, inside}) {
    EXPECT_EQ(expect_sane_answer(kResultantSpeedsPath, &api::kinematics::handle_resultant_speeds,
                                 with_samples(request, 361)),
              200)
        << request.dump();
  }
}

}  // namespace
}  // namespace cutcalc::testing
