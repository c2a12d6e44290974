// Inputs the fuzzers (fuzz/, scripts/ci-fuzz.sh) found to break a promise of the API, minimised,
// each run the way the harness runs it: api::run_json_endpoint with the handler the route table
// registers. Every one must get a promised status (never 500) and a problem body that says which
// field is wrong.

#include <gtest/gtest.h>

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "api/json_endpoint.h"
#include "api/routes.h"
#include "support/quantity_keys.h"

namespace cutcalc::testing {
namespace {

api::ApiResponse run(std::string_view path, std::string_view body) {
  for (const api::CalculationRoute& route : api::calculation_routes()) {
    if (path == route.path) {
      api::ApiResponse response = api::run_json_endpoint(
          {path, "application/json", body, "fuzz", "application/json"}, route.handler);
      api::write_whole(response);
      return response;
    }
  }
  ADD_FAILURE() << "no calculation route " << path;
  return {};
}

// A 422 problem with an entry in errors at `pointer`.
void expect_field_error(const api::ApiResponse& response, const std::string& pointer) {
  ASSERT_EQ(response.status, 422) << response.body;
  EXPECT_EQ(response.content_type, "application/problem+json");
  const auto body = nlohmann::json::parse(response.body, nullptr, false);
  ASSERT_TRUE(body.is_object()) << response.body;
  ASSERT_TRUE(body.contains("errors") && body["errors"].is_array()) << response.body;
  bool found = false;
  for (const auto& error : body["errors"]) {
    found = found || error.value("pointer", std::string("-")) == pointer;
  }
  EXPECT_TRUE(found) << "no error at \"" << pointer << "\": " << response.body;
}

// main_time_fuzzer: entry_feed_factor 5e-324 (a subnormal double, so inside 0 < f <= 1) makes the
// entry feed f * S_m2 so small that the entry time overflows to infinity; the domain reported
// "the result is too large to represent" (not_converged) and the answer was a 500. A positive
// factor too small for any machine must be refused like every other tiny positive input
// (kSmallestPositive, api/field_reader.h): 422 at /entry_feed_factor.
TEST(FuzzRegression, MainTimeSubnormalEntryFeedFactorIsAFieldError) {
  const auto response = run("/v1/main-time", R"({
    "cutter_diameter_mm": 20, "teeth": 4, "spindle_speed_rpm": 1000, "feed_per_tooth_mm": 0.05,
    "entry_feed_factor": 5e-324, "length_mm": 100,
    "entry": {"contour": "straight", "width_mm": 20},
    "exit": {"contour": "straight", "width_mm": 20},
    "allowance": {"width_mm": 20, "width_of_cut_mm": 20, "depth_mm": 2, "depth_of_cut_mm": 2}})");
  expect_field_error(response, "/entry_feed_factor");
}

// entry_length_fuzzer: the oracle took the scheme's lateral limits for lengths and called the
// negative band limit -3 mm a broken promise. It is a coordinate: the frame Y of an arc is measured
// from the arc axis (spec section 3), so with K = 12 and r = 15 the band [K - r, K + r] clipped to
// the strip [-5, 5] is [-3, 5]. Pinned here; both oracles now share support/quantity_keys.h.
TEST(FuzzRegression, EntrySchemeBandOfAnArcIsSignedFrameY) {
  const auto response = run("/v1/entry-length", R"({"approach_mm": 2.0, "cutter_diameter_mm": 30,
    "entry": {"contour": "convex_arc", "radius_mm": 5}, "include_scheme": true, "offset_mm": 12})");
  ASSERT_EQ(response.status, 200) << response.body;
  const auto band = nlohmann::json::parse(response.body).at("scheme").at("entry").at("band");
  EXPECT_NEAR(band.at("y_min_mm").get<double>(), -3.0, 1e-12);
  EXPECT_NEAR(band.at("y_max_mm").get<double>(), 5.0, 1e-12);
}

// polygon_hole_gcode_fuzzer / _text_fuzzer (the 10^6-input report run): two legal requests at the
// edge of the bounds, a 72 m triangle 360 mm deep (117 layers, 613 blocks a loop: an 8.3 MB
// answer) and a 1 km triangle at 1e-6 rpm in c_axis mode (1483 blocks a loop), took over the
// harness's 5 s per-input limit in the sanitized, coverage-instrumented build with its oracle (the
// release service answers them in 0.13 s and 0.03 s). Not hangs: the per-input limit is now 30 s.
// Pinned: both are answered 200 with a whole program under the size cap, never a 500. At 1e-6 rpm
// the S word printed as S0.0000 (a spindle that never turns: the machine-time property step found
// its G95 blocks without feed), now refused (word_prints_as_zero); 1e-4 rpm is the slowest spindle
// the program can state.
TEST(FuzzRegression, PolygonProgramsAtTheEdgeOfTheBoundsAreAnswered) {
  const char* requests[] = {
      R"({"depth_mm": 360.0, "faces": 3, "inscribed_diameter_mm": 72060,
          "spindle_speed_rpm": 31.5, "step_down_mm": 3.1})",
      R"({"depth_mm": 0.2, "faces": 3, "inscribed_diameter_mm": 999999.9999999999,
          "spindle_speed_rpm": 1e-04, "step_down_mm": 180.0,
          "synchronization": "c_axis"})"};
  const auto refused = run("/v1/polygon-hole/gcode", R"({"depth_mm": 0.2, "faces": 3,
      "inscribed_diameter_mm": 999999.9999999999, "spindle_speed_rpm": 1.0000000000000002e-06,
      "step_down_mm": 180.0, "synchronization": "c_axis"})");
  EXPECT_EQ(refused.status, 422) << refused.body;
  EXPECT_NE(refused.body.find("word_prints_as_zero"), std::string::npos) << refused.body;
  for (const char* request : requests) {
    const auto response = run("/v1/polygon-hole/gcode", request);
    ASSERT_EQ(response.status, 200) << request;
    const auto body = nlohmann::json::parse(response.body);
    const auto program = body.at("program").get<std::string>();
    EXPECT_EQ(program.rfind("%\n", 0), 0U) << request;
    EXPECT_GE(program.size(), 3U);
    EXPECT_EQ(program.substr(program.size() - 3), "\n%\n") << request;
    EXPECT_LT(program.size(), std::size_t{16} << 20U) << request;
  }
}

// polygon_hole_gcode_fuzzer (report run, on a box where it ran at low priority beside CI): a 904 m
// triangle 0.1 mm deep at 1e-6 mm a step down (100 000 layers) took 45 s of wall time (2 s of CPU
// in the fuzz build; 18 ms in the release service). Not a hang: it is refused, before any program
// text is written, by the program size cap (section 10: at most 200 000 arc blocks).
TEST(FuzzRegression, PolygonWithAHundredThousandLayersIsRefusedBySizeCap) {
  const auto response = run("/v1/polygon-hole/gcode", R"({"depth_mm": 0.1, "faces": 3,
    "inscribed_diameter_mm": 904000.0, "spindle_speed_rpm": 4,
    "step_down_mm": 1.0000000000000002e-06})");
  ASSERT_EQ(response.status, 422) << response.body;
  EXPECT_NE(response.body.find("200000 arc blocks"), std::string::npos) << response.body;
}

// property step of scripts/ci-contract.sh (boundary case): a flat 1e-6 mm wide on a 1000 m part is
// 2.5e-19 mm deep, below the resolution of R2 in doubles: d rounded to R2, alpha_e to 0, and the
// answer was 200 with zero widths and the G93 blocks `F inf`. With t kept exact the flat is
// computed, and its steps, far below the printed resolution, are refused; so are those of a 1 um
// deep flat there.
TEST(FuzzRegression, LatheFlatBelowTheResolutionOfThePartIsRefused) {
  expect_field_error(run("/v1/lathe-flat", R"({"part_diameter_mm": 1000000,
    "flat_width_mm": 0.000001, "flatness_tolerance_mm": 0.000001, "feed_mm_per_min": 170})"),
                     "");
  expect_field_error(run("/v1/lathe-flat", R"({"part_diameter_mm": 1000000,
    "flat_depth_mm": 0.000001, "steps": 4, "feed_mm_per_min": 170})"),
                     "");
}

}  // namespace
}  // namespace cutcalc::testing

namespace cutcalc::testing {
namespace {

// program_time_fuzzer (its first run): a square blended without a tolerance is shorter than
// programmed, so its dynamics_time_min (T_e - T_n) is negative, as machine-time.md section 6
// says; the oracle took every *_min for a time that cannot be negative
// (support/quantity_keys.h now lists it as signed).
TEST(FuzzRegression, BlendedSquareLosesNegativeTimeToDynamics) {
  const auto response = run("/v1/program-time", R"({"program":
      "G21 G90 G17 G64\nF4000\nG1 X60\nG1 Y60\nG1 X0\nG1 Y0\nM2\n", "machine": {"axes": {
      "x": {"max_velocity_mm_per_min": 12000, "max_acceleration_mm_per_s2": 1000},
      "y": {"max_velocity_mm_per_min": 12000, "max_acceleration_mm_per_s2": 1000}}}})");
  ASSERT_EQ(response.status, 200) << response.body;
  EXPECT_LT(nlohmann::json::parse(response.body).at("dynamics_time_min").get<double>(), 0.0);
  EXPECT_FALSE(test_support::is_non_negative_quantity("dynamics_time_min"));
}

}  // namespace
}  // namespace cutcalc::testing
