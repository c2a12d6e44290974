// The "v razvod" cycle's geometry, pattern, times, roughness and chip (grooving-cycle.md K1-K22),
// with values derived by hand from the equations or restated from the worked example (section 7).

#include "domain/grooving/grooving_cycle.h"
#include "domain/grooving/grooving_settings.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace cutcalc::domain::grooving {
namespace {

using settings::paper_setting;
using settings::small_groove;

GroovingCycleResult computed(const GroovingCycleParams& p) {
  const auto result = compute_grooving_cycle(p);
  EXPECT_TRUE(result.ok()) << error_code_name(result.ok() ? ErrorCode::not_converged
                                                          : result.error().code);
  return result.ok() ? result.value() : GroovingCycleResult{};
}

TEST(GroovingCycleGeometry, BottomFollowsFromTheDepthAndTheDepthFromTheBottom) {
  // K1 both ways: h 4.8 -> Db = 220 - 9.6; Db 210.4 -> h = (220 - 210.4)/2.
  const GroovingCycleResult by_depth = computed(paper_setting());
  EXPECT_NEAR(by_depth.bottom_diameter_mm, 210.4, 1e-12);
  EXPECT_NEAR(by_depth.groove_depth_mm, 4.8, 1e-12);
  GroovingCycleParams p = paper_setting();
  p.groove_depth_mm.reset();
  p.bottom_diameter_mm = 200.0;
  const GroovingCycleResult by_bottom = computed(p);
  EXPECT_NEAR(by_bottom.groove_depth_mm, 10.0, 1e-12);
  EXPECT_EQ(by_bottom.bottom_diameter_mm, 200.0);
}

TEST(GroovingCycleGeometry, ApproachDiameterIsTheStartPlusTwiceTheClearance) {
  // K2: D_a = D0 + 2c.
  EXPECT_NEAR(computed(paper_setting()).approach_diameter_mm, 222.0, 1e-12);
  GroovingCycleParams p = paper_setting();
  p.approach_clearance_mm = 2.5;
  EXPECT_NEAR(computed(p).approach_diameter_mm, 225.0, 1e-12);
}

TEST(GroovingCycleGeometry, ToolWidthAndShiftFillTheGrooveWhicheverIsGiven) {
  // K3: both given and consistent.
  GroovingCycleParams p = paper_setting();
  p.tool_width_mm = 10.0;
  GroovingCycleResult r = computed(p);
  EXPECT_NEAR(r.tool_width_mm, 10.0, 1e-12);
  EXPECT_NEAR(r.shift_mm, 0.4, 1e-12);
  // Only B: X2 = W - B.
  p.shift_mm.reset();
  p.tool_width_mm = 9.95;
  r = computed(p);
  EXPECT_NEAR(r.shift_mm, 0.45, 1e-12);
  EXPECT_NEAR(r.tool_width_mm, 9.95, 1e-12);
  // Only X2: B = W - X2.
  p.tool_width_mm.reset();
  p.shift_mm = 0.35;
  r = computed(p);
  EXPECT_NEAR(r.tool_width_mm, 10.05, 1e-12);
  EXPECT_NEAR(r.shift_mm, 0.35, 1e-12);
  // Neither: X2 = min(0.4, W/3): 0.4 in a wide groove, W/3 below W = 1.2.
  p.shift_mm.reset();
  EXPECT_NEAR(computed(p).shift_mm, 0.4, 1e-12);
  p.groove_width_mm = 0.9;
  r = computed(p);
  EXPECT_NEAR(r.shift_mm, 0.3, 1e-12);
  EXPECT_NEAR(r.tool_width_mm, 0.6, 1e-12);
  p.groove_width_mm = 1.2;
  EXPECT_NEAR(computed(p).shift_mm, 0.4, 1e-12);
}

TEST(GroovingCycleGeometry, ToolAndShiftMustAddUpToTheWidthWithinARelativeBillionth) {
  // K3: |B + X2 - W| <= 1e-9 W accepted, beyond refused.
  GroovingCycleParams p = paper_setting();
  p.tool_width_mm = 10.0 + 0.5e-9 * 10.4;
  EXPECT_TRUE(compute_grooving_cycle(p).ok());
  p.tool_width_mm = 10.0 + 2e-9 * 10.4;
  auto refused = compute_grooving_cycle(p);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, ErrorCode::tool_and_shift_mismatch);
  p.tool_width_mm = 9.9;
  refused = compute_grooving_cycle(p);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, ErrorCode::tool_and_shift_mismatch);
}

TEST(GroovingCycleGeometry, ToolMustBeWiderThanTheShift) {
  // K4: B > X2; B = X2 and B < X2 refused, just wider accepted.
  GroovingCycleParams p = paper_setting();
  p.groove_width_mm = 1.0;
  for (const double shift : {0.5, 0.6}) {
    p.shift_mm = shift;
    const auto refused = compute_grooving_cycle(p);
    ASSERT_FALSE(refused.ok()) << shift;
    EXPECT_EQ(refused.error().code, ErrorCode::tool_not_wider_than_shift) << shift;
  }
  p.shift_mm = 0.49;
  EXPECT_NEAR(computed(p).tool_width_mm, 0.51, 1e-12);
  // The default shift (W/3) never trips K4.
  p.shift_mm.reset();
  p.groove_width_mm = 0.3;
  EXPECT_NEAR(computed(p).shift_mm, 0.1, 1e-12);
}

TEST(GroovingCycleRevolutions, RevolutionsRoundUpButNotForAFloatingPointHair) {
  // K7: N = max(1, ceil(h/S0 - 1e-9)). 1.08/0.12 = 9.000000000000002 in binary: N = 9, not 10.
  GroovingCycleParams p = paper_setting();
  p.groove_depth_mm = 1.08;
  ASSERT_GT(1.08 / 0.12, 9.0);
  EXPECT_EQ(computed(p).revolutions, 9);
  // The worked example: 4.8/0.12 -> 40.
  EXPECT_EQ(computed(paper_setting()).revolutions, 40);
  // Not a multiple: 4.81/0.12 = 40.08 -> 41.
  p.groove_depth_mm = 4.81;
  EXPECT_EQ(computed(p).revolutions, 41);
  // Shallower than one feed: one revolution.
  p.groove_depth_mm = 0.05;
  EXPECT_EQ(computed(p).revolutions, 1);
}

TEST(GroovingCycleRevolutions, InfeedIsTheDepthSharedEquallyAndAtMostTheFeed) {
  // K8: s = h/N; = S0 when h is a multiple of S0.
  EXPECT_NEAR(computed(paper_setting()).infeed_per_revolution_mm, 0.12, 1e-15);
  GroovingCycleParams p = paper_setting();
  p.groove_depth_mm = 4.81;
  const GroovingCycleResult r = computed(p);
  EXPECT_NEAR(r.infeed_per_revolution_mm, 4.81 / 41.0, 1e-15);
  EXPECT_LE(r.infeed_per_revolution_mm, 0.12);
  // Counts of section 3.7: 41 = 21 radial + 20 shift revolutions, 21 shifts with the final one.
  EXPECT_EQ(r.radial_revolutions, 21);
  EXPECT_EQ(r.shift_revolutions, 20);
  EXPECT_EQ(r.shifts, 21);
  EXPECT_NEAR(r.final_shift_revolutions, 0.4 / (4.81 / 41.0), 1e-12);
  // c/s + N + n_d + X2/s.
  EXPECT_NEAR(r.spindle_revolutions, (1.0 + 0.4) / (4.81 / 41.0) + 41.0 + 1.0, 1e-9);
}

TEST(GroovingCycleRevolutions, DiametersStepEquallyAndTheLastIsTheBottomExactly) {
  // K9: D_k = D0 - 2 h k/N, D_N = Db as given. With D0 220 and Db 49.3 in one revolution,
  // 220 - 2 ((220 - 49.3)/2) is not 49.3 in binary: the set value must win.
  GroovingCycleParams p = paper_setting();
  p.groove_depth_mm.reset();
  p.bottom_diameter_mm = 49.3;
  p.feed_per_rev_mm = 100.0;
  const double h = (220.0 - 49.3) / 2.0;
  ASSERT_NE(220.0 - 2.0 * h, 49.3);
  GroovingCycleResult r = computed(p);
  ASSERT_EQ(r.pattern.size(), 1U);
  EXPECT_EQ(r.pattern.back().diameter_mm, 49.3);
  // The worked example: 40 steps of 0.24 mm in diameter, the last exactly 210.4.
  r = computed(paper_setting());
  ASSERT_EQ(r.pattern.size(), 40U);
  for (std::size_t k = 1; k <= r.pattern.size(); ++k) {
    EXPECT_NEAR(r.pattern[k - 1].diameter_mm, 220.0 - 0.24 * static_cast<double>(k), 1e-12) << k;
  }
  EXPECT_EQ(r.pattern.back().diameter_mm, r.bottom_diameter_mm);
}

TEST(GroovingCycleRevolutions, OddRevolutionsPlungeEvenOnesShiftAlternately) {
  // K10-K11: k odd radial; k = 2 mod 4 to z_R, k = 0 mod 4 back to z_L; f_sh = sqrt(s^2 + X2^2).
  const GroovingCycleResult r = computed(small_groove(8));
  ASSERT_EQ(r.pattern.size(), 8U);
  const Side sides[] = {Side::left, Side::right, Side::right, Side::left,
                        Side::left, Side::right, Side::right, Side::left};
  for (std::size_t i = 0; i < 8; ++i) {
    EXPECT_EQ(r.pattern[i].shifts, (i + 1) % 2 == 0) << i + 1;
    EXPECT_EQ(r.pattern[i].side, sides[i]) << i + 1;
  }
  EXPECT_NEAR(r.right_z_mm, -9.6, 1e-12);
  EXPECT_NEAR(r.shift_feed_mm_per_rev, std::sqrt(0.1 * 0.1 + 0.4 * 0.4), 1e-12);
  EXPECT_NEAR(computed(paper_setting()).shift_feed_mm_per_rev, 0.417612, 0.5e-6);
}

TEST(GroovingCycleRevolutions, PatternEndsLeftForNMod4Of0And1ElseRight) {
  // K12, and the final shift goes to the other side.
  struct Case {
    int n;
    Side pattern_end;
  };
  for (const Case c : {Case{4, Side::left}, Case{5, Side::left}, Case{6, Side::right},
                       Case{7, Side::right}, Case{1, Side::left}, Case{2, Side::right}}) {
    const GroovingCycleResult r = computed(small_groove(c.n));
    ASSERT_EQ(r.revolutions, c.n);
    EXPECT_EQ(r.pattern_end_side, c.pattern_end) << c.n;
    EXPECT_EQ(r.pattern.back().side, c.pattern_end) << c.n;
    EXPECT_NE(r.end_side, c.pattern_end) << c.n;
  }
}

TEST(GroovingCycleTimes, ConstantSpeedTimesAreRevolutionsOverN) {
  // K17-K20 under G97 (K16: M = 1/n), derived by hand for N = 7, s 0.1, c 1, X2 0.4, n 500:
  // approach 10 rev, plunge 4, shift 3, dwell 1, final shift 4, retract (52 - 48.6)/2 / 10000.
  const GroovingCycleResult r = computed(small_groove(7));
  EXPECT_NEAR(r.approach_time_min, 10.0 / 500.0, 1e-12);
  EXPECT_NEAR(r.plunge_time_min, 4.0 / 500.0, 1e-12);
  EXPECT_NEAR(r.shift_time_min, 3.0 / 500.0, 1e-12);
  EXPECT_NEAR(r.dwell_time_min, 1.0 / 500.0, 1e-12);
  EXPECT_NEAR(r.dwell_seconds, 0.12, 1e-12);
  EXPECT_NEAR(r.final_shift_time_min, 4.0 / 500.0, 1e-12);
  EXPECT_NEAR(r.retract_time_min, 1.7 / 10000.0, 1e-15);
  EXPECT_NEAR(r.cycle_time_min, 22.0 / 500.0 + 1.7 / 10000.0, 1e-12);
  EXPECT_NEAR(r.spindle_speed_at_start_rpm, 500.0, 1e-9);
  EXPECT_NEAR(r.spindle_speed_at_bottom_rpm, 500.0, 1e-9);
}

TEST(GroovingCycleTimes, WorkedExampleTimesUnderConstantSurfaceSpeed) {
  // Section 7, printed to 6 decimals (retract to 5).
  const GroovingCycleResult r = computed(paper_setting());
  EXPECT_NEAR(r.approach_time_min, 0.067276, 0.5e-6);
  EXPECT_NEAR(r.plunge_time_min, 0.157313, 0.5e-6);
  EXPECT_NEAR(r.shift_time_min, 0.157138, 0.5e-6);
  EXPECT_NEAR(r.dwell_time_min, 0.007686, 0.5e-6);
  EXPECT_NEAR(r.dwell_seconds, 0.461, 0.5e-3);
  EXPECT_NEAR(r.final_shift_time_min, 0.025620, 0.5e-6);
  EXPECT_NEAR(r.retract_time_min, 0.00058, 1e-12);
  EXPECT_NEAR(r.cycle_time_min, 0.415614, 0.5e-6);
  EXPECT_NEAR(r.cycle_time_min,
              r.approach_time_min + r.plunge_time_min + r.shift_time_min + r.dwell_time_min +
                  r.final_shift_time_min + r.retract_time_min,
              1e-15);
  EXPECT_NEAR(r.spindle_speed_at_start_rpm, 124.430, 0.5e-3);
  EXPECT_NEAR(r.spindle_speed_at_bottom_rpm, 130.108, 0.5e-3);
  // K19: the bottom's times from n(Db), also when G96 is clamped there.
  GroovingCycleParams clamped = paper_setting();
  clamped.spindle.max_spindle_rpm = 128.0;
  const GroovingCycleResult c = computed(clamped);
  EXPECT_NEAR(c.spindle_speed_at_bottom_rpm, 128.0, 1e-9);
  EXPECT_NEAR(c.dwell_time_min, 1.0 / 128.0, 1e-15);
  EXPECT_NEAR(c.final_shift_time_min, (0.4 / 0.12) / 128.0, 1e-15);
}

TEST(GroovingCycleWall, PitchIsFourInfeedsAndRzComesFromTheWallRoughness) {
  // K21: pitch 4 s; Rz and branch of roughness.md at S = 4 s; plain plunge at S = S0.
  const GroovingCycleResult r = computed(paper_setting());
  EXPECT_NEAR(r.wall_pitch_mm, 0.48, 1e-15);
  const auto wall = roughness::compute_groove_wall_roughness({0.48, 0.3, 2.0, std::nullopt});
  ASSERT_TRUE(wall.ok());
  EXPECT_NEAR(r.wall_rz_um, wall.value().rz_um, 1e-12);
  EXPECT_EQ(r.wall_rz_branch, wall.value().branch);
  const auto plain = roughness::compute_groove_wall_roughness({0.12, 0.3, 2.0, std::nullopt});
  ASSERT_TRUE(plain.ok());
  EXPECT_NEAR(r.plain_plunge_rz_um, plain.value().rz_um, 1e-12);
  // Section 7's numbers.
  EXPECT_NEAR(r.wall_rz_um, 13.4746, 0.5e-4);
  EXPECT_EQ(r.wall_rz_branch, roughness::CrestBranch::nose_arc_and_minor_edge);
  EXPECT_NEAR(r.plain_plunge_rz_um, 2.6248, 0.5e-4);
  // Not a multiple of S0: the pitch follows s, not S0.
  GroovingCycleParams p = paper_setting();
  p.groove_depth_mm = 4.81;
  EXPECT_NEAR(computed(p).wall_pitch_mm, 4.0 * 4.81 / 41.0, 1e-15);
}

TEST(GroovingCycleChip, ChipIsTheInfeedAndTheSideChipIsClampedAtZero) {
  // K22: h = s; side = max(0, X2 cos phi1 - s sin phi1).
  const GroovingCycleResult r = computed(paper_setting());
  EXPECT_NEAR(r.chip_thickness_mm, 0.12, 1e-15);
  const double phi1 = 2.0 * std::numbers::pi / 180.0;
  EXPECT_NEAR(r.side_chip_thickness_mm, 0.4 * std::cos(phi1) - 0.12 * std::sin(phi1), 1e-15);
  EXPECT_NEAR(r.side_chip_thickness_mm, 0.395568, 0.5e-6);
  // phi1 89 deg, X2 0.3, s 0.5: 0.3 cos 89 - 0.5 sin 89 < 0 -> 0.
  GroovingCycleParams p = paper_setting();
  p.shift_mm = 0.3;
  p.minor_edge_angle_deg = 89.0;
  p.feed_per_rev_mm = 0.5;
  p.groove_depth_mm = 5.0;
  const GroovingCycleResult clamped = computed(p);
  EXPECT_NEAR(clamped.infeed_per_revolution_mm, 0.5, 1e-15);
  EXPECT_EQ(clamped.side_chip_thickness_mm, 0.0);
}

}  // namespace
}  // namespace cutcalc::domain::grooving
