// Broken and extreme /v1/resultant-speeds requests: the right 4xx and pointer, never a 500, a NaN
// or an infinity.

#include <gtest/gtest.h>

#include <array>
#include <random>

#include "api/kinematics/resultant_speeds_endpoint.h"
#include "support/reference_compare.h"
#include "support/route_paths.h"
#include "support/sanity_checks.h"
#include "support/test_server.h"

namespace cutcalc::testing {
namespace {

using nlohmann::json;

json bad_input_sample() {
  return {{"tool_radius_mm", 10},       {"workpiece_radius_mm", 16}, {"flat_depth_mm", 1},
          {"tool_speed_rpm", 3000},     {"workpiece_speed_rpm", 10}, {"milling", "up"},
          {"tool_feed_mm_per_min", 100}};
}

TEST(ResultantSpeedsBadInput, EveryFieldErrorIsListedWithItsPointer) {
  json request = bad_input_sample();
  request["tool_radius_mm"] = "10";
  request["workpiece_speed_rpm"] = -1;
  request["milling"] = "climb";
  request["edge_inclination_deg"] = 90;
  request["contact_angles_deg"] = json::array({0, "x", nullptr});
  const JsonReply reply = post(kResultantSpeedsPath, request.dump());
  EXPECT_EQ(reply.status, 422) << reply.body;
  for (const char* pointer :
       {"/tool_radius_mm", "/workpiece_speed_rpm", "/milling", "/edge_inclination_deg",
        "/contact_angles_deg/1", "/contact_angles_deg/2"}) {
    EXPECT_TRUE(problem_names_pointer(reply.json, pointer)) << pointer << ": " << reply.body;
  }
}

TEST(ResultantSpeedsBadInput, EmptyOrNonListAnglesNameTheList) {
  for (const json& angles : {json::array(), json("0"), json::object()}) {
    json request = bad_input_sample();
    request["contact_angles_deg"] = angles;
    const JsonReply reply = post(kResultantSpeedsPath, request.dump());
    EXPECT_EQ(reply.status, 422);
    EXPECT_TRUE(problem_names_pointer(reply.json, "/contact_angles_deg")) << reply.body;
  }
}

TEST(ResultantSpeedsBadInput, OverflowingAngleNamesItsIndex) {
  const std::string body =
      bad_input_sample().dump().insert(1, R"("contact_angles_deg": [0, 1e400], )");
  const JsonReply reply = post(kResultantSpeedsPath, body);
  EXPECT_EQ(reply.status, 422) << reply.body;
  EXPECT_TRUE(problem_names_pointer(reply.json, "/contact_angles_deg/1")) << reply.body;
}

TEST(ResultantSpeedsBadInput, NeitherPlacementIsACombinationError) {
  json request = bad_input_sample();
  request.erase("flat_depth_mm");
  const JsonReply reply = post(kResultantSpeedsPath, request.dump());
  EXPECT_EQ(reply.status, 422);
  EXPECT_TRUE(problem_names_pointer(reply.json, ""));
}

TEST(ResultantSpeedsBadInput, RandomExtremeRequestsAreAnsweredSanely) {
  std::mt19937_64 engine(2026);
  static constexpr std::array<double, 12> kExtremes = {0.0,  1e-300, 1e-9, 0.5, 1.0,  9.99,
                                                       10.0, 16.0,   26.0, 1e6, -1e6, 1e300};
  const auto any = [&engine] {
    if (std::uniform_int_distribution<int>(0, 2)(engine) == 0) {
      return kExtremes[std::uniform_int_distribution<std::size_t>(0, kExtremes.size() - 1)(engine)];
    }
    return std::uniform_real_distribution<double>(-5.0, 40.0)(engine);
  };
  int answered = 0;
  for (int i = 0; i < 1500 && !HasFailure(); ++i) {
    json request = bad_input_sample();
    for (const char* key : {"tool_radius_mm", "workpiece_radius_mm", "flat_depth_mm",
                            "tool_speed_rpm", "workpiece_speed_rpm", "tool_feed_mm_per_min"}) {
      if (std::uniform_int_distribution<int>(0, 3)(engine) == 0) {
        request[key] = any();
      }
    }
    if (std::uniform_int_distribution<int>(0, 2)(engine) == 0) {
      request.erase("flat_depth_mm");
      request["center_distance_mm"] = any();
    }
    if (std::uniform_int_distribution<int>(0, 2)(engine) == 0) {
      request["contact_angles_deg"] = json::array({any() * 5.0, 0.0, -any()});
    }
    request["milling"] = std::uniform_int_distribution<int>(0, 1)(engine) == 0 ? "up" : "down";
    if (expect_sane_answer(kResultantSpeedsPath, &api::kinematics::handle_resultant_speeds,
                           request) == 200) {
      ++answered;
    }
  }
  EXPECT_GT(answered, 300) << "too few requests reached the domain";
}

}  // namespace
}  // namespace cutcalc::testing
