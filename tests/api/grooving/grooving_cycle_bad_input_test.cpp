// Broken and extreme grooving-cycle requests through the handler: 200 or 422 only, never a 500, a
// NaN or an infinity, no negative length, and every answer (programs included) within openapi.yaml.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "api/grooving/grooving_cycle_endpoint.h"
#include "support/extreme_numbers.h"
#include "support/sanity_checks.h"

namespace cutcalc::testing {
namespace {

using nlohmann::json;

TEST(GroovingCycleBadInput, RandomExtremeRequestsAreAnsweredSanely) {
  ExtremeNumbers numbers(21, {0.0, 1e-300, 1e-9, 0.12, 0.4, 10.4, 220.0, 1e6, -1.0, 1e300});
  const auto any = [&numbers] { return numbers.any(); };
  const auto pick = [&numbers](int n) { return numbers.pick(n); };
  static constexpr std::array<const char*, 3> kDialects = {"linuxcnc", "fanuc", "sinumerik"};
  int answered = 0;
  for (int i = 0; i < 400 && !HasFailure(); ++i) {
    const double start = any();
    json request = {{"groove_width_mm", any()},
                    {"start_diameter_mm", start},
                    {"groove_left_z_mm", numbers.uniform(-500, 500)},
                    {"feed_per_rev_mm", any()},
                    {"nose_radius_mm", any()},
                    {"minor_edge_angle_deg", numbers.uniform(0.0, 89.999)}};
    if (pick(2) == 0) {
      request["groove_depth_mm"] = start * numbers.uniform(0.0, 0.6);
    } else {
      request["bottom_diameter_mm"] = start * numbers.uniform(0.0, 1.1);
    }
    if (pick(3) == 0) request["shift_mm"] = any();
    if (pick(3) == 0) request["tool_width_mm"] = any();
    if (pick(2) == 0) {
      request["spindle_speed_rpm"] = any();
      if (pick(2) == 0) request["max_spindle_rpm"] = any();
    } else {
      request["cutting_speed_m_per_min"] = any();
      request["max_spindle_rpm"] = any();
    }
    if (pick(3) == 0) request["dwell_revolutions"] = pick(2) == 0 ? 0.0 : any();
    if (pick(3) == 0) request["approach_clearance_mm"] = any();
    request["program"] = {{"dialect", kDialects[static_cast<std::size_t>(pick(3))]},
                          {"units", pick(2) == 0 ? "mm" : "inch"},
                          {"decimals", 3 + pick(4)}};
    if (expect_sane_answer("/v1/grooving/cycle", &api::grooving::handle_grooving_cycle, request) ==
        200) {
      ++answered;
    }
  }
  // Enough requests get through to check the answers, not only the refusals.
  EXPECT_GT(answered, 40);  // 62 of the 400 with this seed
}

}  // namespace
}  // namespace cutcalc::testing
