// POST /v1/polygon-hole/gcode, spec polygon-holes.md section 13: the rotor, the hole's corner
// radius and the machining time in every answer, and the top-level rapid_mm_per_min (the values
// themselves are replayed from shared/reference/next/polygon-hole.json by ReferenceReplay).

#include <gtest/gtest.h>

#include <string>

#include "support/project_contract.h"
#include "support/route_paths.h"
#include "support/test_server.h"

namespace cutcalc::testing {
namespace {

using nlohmann::json;

json square_hole() {
  return {{"faces", 4},
          {"inscribed_diameter_mm", 16.0},
          {"depth_mm", 0.2},
          {"step_down_mm", 0.1},
          {"spindle_speed_rpm", 30}};
}

JsonReply post_and_check(const json& request) {
  const JsonReply reply = post(kPolygonGcodePath, request.dump());
  expect_conforms(kPolygonGcodePath, reply);
  return reply;
}

TEST(PolygonRotorAndTime, EveryAnswerHasTheRotorTheCornerRadiusAndTheTimes) {
  for (int faces = 3; faces <= 12; ++faces) {
    json request = square_hole();
    request["faces"] = faces;
    const JsonReply reply = post_and_check(request);
    ASSERT_EQ(reply.status, 200) << reply.body;
    const json& rotor = reply.json.at("rotor");
    EXPECT_EQ(rotor.at("corners"), faces - 1);
    EXPECT_EQ(rotor.at("flank_arcs").size(), static_cast<std::size_t>(faces - 2));
    EXPECT_LE(rotor.at("neck_diameter_max_mm").get<double>(),
              rotor.at("width_min_mm").get<double>());
    EXPECT_GE(reply.json.at("corner_radius_mm").get<double>(), 0.0);
    const double sum = reply.json.at("working_time_min").get<double>() +
                       reply.json.at("plunge_time_min").get<double>() +
                       reply.json.at("rapid_time_min").get<double>();
    EXPECT_NEAR(reply.json.at("cycle_time_min").get<double>(), sum, 1e-15);
  }
}

TEST(PolygonRotorAndTime, RapidRateChangesOnlyTheRapidTime) {
  const JsonReply standard = post_and_check(square_hole());
  json faster = square_hole();
  faster["rapid_mm_per_min"] = 20000;
  const JsonReply reply = post_and_check(faster);
  ASSERT_EQ(reply.status, 200) << reply.body;
  EXPECT_NEAR(reply.json.at("rapid_time_min").get<double>(),
              0.5 * standard.json.at("rapid_time_min").get<double>(), 1e-15);
  json without_times = reply.json;
  json standard_without = standard.json;
  for (const char* key : {"rapid_time_min", "cycle_time_min"}) {
    without_times.erase(key);
    standard_without.erase(key);
  }
  EXPECT_EQ(without_times, standard_without);
}

TEST(PolygonRotorAndTime, RapidRateIsTopLevelAndPositive) {
  for (const json& bad : {json(0), json(-1), json("fast"), json(nullptr)}) {
    json request = square_hole();
    request["rapid_mm_per_min"] = bad;
    const JsonReply reply = post_and_check(request);
    EXPECT_EQ(reply.status, 422) << bad.dump();
    ASSERT_TRUE(reply.json.contains("errors")) << reply.body;
    EXPECT_EQ(reply.json.at("errors").at(0).at("pointer"), "/rapid_mm_per_min") << reply.body;
  }
  json in_program = square_hole();
  in_program["program"] = {{"rapid_mm_per_min", 20000}};
  const JsonReply reply = post_and_check(in_program);
  EXPECT_EQ(reply.status, 422);
  EXPECT_EQ(reply.json.at("errors").at(0).at("pointer"), "/program/rapid_mm_per_min") << reply.body;
}

}  // namespace
}  // namespace cutcalc::testing
