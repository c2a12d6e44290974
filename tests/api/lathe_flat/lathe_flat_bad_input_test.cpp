// Broken and extreme lathe-flat requests through the handler: 200 or 422 only, never a 500, a NaN
// or an infinity, no negative length, and every answer (programs included) within openapi.yaml.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "api/lathe_flat/lathe_flat_endpoint.h"
#include "support/extreme_numbers.h"
#include "support/sanity_checks.h"

namespace cutcalc::testing {
namespace {

using nlohmann::json;

TEST(LatheFlatBadInput, RandomExtremeRequestsAreAnsweredSanely) {
  ExtremeNumbers numbers(22, {0.0, 1e-300, 1e-9, 0.5, 1.0, 16.0, 32.0, 1e6, -1.0, 1e300});
  const auto any = [&numbers] { return numbers.any(); };
  const auto pick = [&numbers](int n) { return numbers.pick(n); };
  const auto fraction = [&numbers](double high) { return numbers.uniform(0.0, high); };
  static constexpr std::array<const char*, 4> kGeometry = {"flat_depth_mm", "flat_width_mm",
                                                           "axis_distance_mm", "across_flats_mm"};
  static constexpr std::array<const char*, 3> kDialects = {"linuxcnc", "sinumerik", "fanuc"};
  int answered = 0;
  for (int i = 0; i < 300 && !HasFailure(); ++i) {
    const double diameter = any();
    json request = {{"part_diameter_mm", diameter}, {"feed_mm_per_min", any()}};
    // Mostly one geometry member, scaled to the part (inside or a little beyond); sometimes none
    // or two.
    const int geometry_count = pick(8) == 0 ? pick(3) : 1;
    for (int g = 0; g < geometry_count; ++g) {
      const char* key = kGeometry[static_cast<std::size_t>(pick(4))];
      const bool radial =
          std::string(key) == "flat_depth_mm" || std::string(key) == "axis_distance_mm";
      request[key] = pick(5) == 0 ? any() : diameter * fraction(radial ? 0.55 : 1.1);
    }
    if (pick(2) == 0) request["flats"] = pick(10) == 0 ? 13 : 1 + pick(12);
    if (pick(2) == 0) request["tool_radius_mm"] = pick(4) == 0 ? 0.0 : any();
    if (pick(4) != 0) request["steps"] = pick(10) == 0 ? 1001 : 1 + pick(pick(4) == 0 ? 1000 : 40);
    if (pick(3) == 0) request["flatness_tolerance_mm"] = std::pow(10.0, -6.5 + fraction(6.7));
    if (pick(3) == 0) request["layer_depth_mm"] = any();
    if (pick(4) == 0) request["block_time_ms"] = any();
    if (pick(4) == 0) request["clearance_mm"] = any();
    if (pick(4) == 0) request["z_mm"] = numbers.uniform(-500, 500);
    request["program"] = {
        {"dialect", kDialects[static_cast<std::size_t>(pick(pick(10) == 0 ? 3 : 2))]},
        {"units", pick(2) == 0 ? "mm" : "inch"},
        {"decimals", 3 + pick(4)}};
    if (expect_sane_answer("/v1/lathe-flat", &api::lathe_flat::handle_lathe_flat, request) == 200) {
      ++answered;
    }
  }
  // Enough requests get through to check the answers, not only the refusals.
  EXPECT_GT(answered, 40);  // 73 of the 300 with this seed
}

TEST(LatheFlatBadInput, FlatsThroughTheAxisAndOnHugePartsAreAnsweredSanely) {
  // At the field bounds: a flat a hair off the axis (alpha_e -> 90 deg, tan ~ 1e16) with the
  // largest feed, steps and tool; a 1 um flat on a 1 km part; a 12-gon of them by tolerance.
  for (const json& request : {json{{"part_diameter_mm", 2},
                                   {"flat_depth_mm", 0.9999999999999999},
                                   {"steps", 1000},
                                   {"feed_mm_per_min", 1e6}},
                              json{{"part_diameter_mm", 2},
                                   {"flat_width_mm", 1.9999999999999998},
                                   {"steps", 1000},
                                   {"feed_mm_per_min", 1e6},
                                   {"tool_radius_mm", 5},
                                   {"program", {{"decimals", 6}}}},
                              json{{"part_diameter_mm", 1e6},
                                   {"flat_depth_mm", 1e-6},
                                   {"flats", 12},
                                   {"flatness_tolerance_mm", 1e-6},
                                   {"feed_mm_per_min", 1e6},
                                   {"program", {{"dialect", "sinumerik"}, {"decimals", 6}}}}}) {
    EXPECT_EQ(expect_sane_answer("/v1/lathe-flat", &api::lathe_flat::handle_lathe_flat, request),
              200)
        << request;
  }
  // The same 1 um flat at 1000 steps in inches: its steps move less than the 5 printed decimals,
  // so its blocks would stand still (steps_below_resolution).
  const json too_fine{{"part_diameter_mm", 1e6},
                      {"flat_depth_mm", 1e-6},
                      {"steps", 1000},
                      {"feed_mm_per_min", 1e6},
                      {"program", {{"units", "inch"}}}};
  EXPECT_EQ(expect_sane_answer("/v1/lathe-flat", &api::lathe_flat::handle_lathe_flat, too_fine),
            422)
      << too_fine;
}

}  // namespace
}  // namespace cutcalc::testing
