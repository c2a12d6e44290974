// Unit tests: passes, lateral placement, feeds and main time (spec entry-and-main-time.md 7, 14).

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "domain/entry/closed_forms.h"
#include "domain/entry/entry_test_support.h"
#include "domain/entry/main_time.h"

namespace {

namespace oracle = cutcalc::test::entry_oracle;
using cutcalc::domain::ErrorCode;
using cutcalc::domain::entry::Allowance;
using cutcalc::domain::entry::compute_main_time;
using cutcalc::domain::entry::CuttingSpeed;
using cutcalc::domain::entry::EntryFeedFactor;
using cutcalc::domain::entry::EntryFeedPerTooth;
using cutcalc::domain::entry::MainTimeParams;
using cutcalc::domain::entry::MainTimeResult;
using cutcalc::domain::entry::SpindleSpeed;
using cutcalc::test::convex_contour;
using cutcalc::test::main_time_ok;
using cutcalc::test::main_time_worked_example;
using cutcalc::test::outcome;
using cutcalc::test::straight_contour;
using cutcalc::test::wall_contour;

using cutcalc::test::kMin;
using cutcalc::test::kMm;
constexpr double kPrinted = 1e-9;  // numbers the spec prints to 10 decimals (rounding 5e-11)

// One lateral pass (N1 = 1) on a straight part: D = 20, z = 4, n = 1000, S_z = 0.05, B = 60.
MainTimeParams single_pass() {
  MainTimeParams p;
  p.cutter_diameter_mm = 20.0;
  p.teeth = 4;
  p.speed = SpindleSpeed{1000.0};
  p.feed_per_tooth_mm = 0.05;
  p.length_mm = 100.0;
  p.entry = straight_contour(60.0);
  p.exit = straight_contour(60.0);
  p.offset_mm = 0.0;
  p.allowance = Allowance{20.0, 20.0, 2.0, 2.0};
  return p;
}

// E34-E36 must hold for any result: per-pass times from lengths and feeds, totals = N2 x sums.
void expect_time_identities(const MainTimeResult& v) {
  double entry = 0.0;
  double steady = 0.0;
  for (std::size_t i = 0; i < v.lateral_passes.size(); ++i) {
    const auto& p = v.lateral_passes[i];
    EXPECT_NEAR(p.entry_time_min, p.entry_length_mm / v.entry_feed_mm_per_min, kMin)
        << "pass " << i;
    EXPECT_NEAR(p.steady_time_min, (p.working_stroke_mm - p.entry_length_mm) / v.feed_mm_per_min,
                kMin)
        << "pass " << i;
    EXPECT_NEAR(p.time_min, p.entry_time_min + p.steady_time_min, kMin) << "pass " << i;
    entry += p.entry_time_min;
    steady += p.steady_time_min;
  }
  const double n2 = static_cast<double>(v.depth_passes_mm.size());
  EXPECT_NEAR(v.entry_time_min, n2 * entry, kMin);
  EXPECT_NEAR(v.steady_time_min, n2 * steady, kMin);
  EXPECT_NEAR(v.main_time_min, n2 * (entry + steady), kMin);
}

void expect_error(const MainTimeParams& p, ErrorCode code, const char* what) {
  const auto res = compute_main_time(p);
  ASSERT_FALSE(res.ok()) << what << ": expected " << cutcalc::domain::error_code_name(code);
  EXPECT_EQ(res.error().code, code) << what << ": got " << outcome(res);
}

}  // namespace

// ---- section 14: the worked example, every number
// --------------------------------------------------

TEST(MainTimeWorkedExample, Feeds) {
  const auto v = main_time_ok(main_time_worked_example());
  EXPECT_NEAR(v.spindle_speed_rpm, 1000.0, kMm);
  EXPECT_NEAR(v.feed_per_rev_mm, 0.4, kMm);
  EXPECT_NEAR(v.feed_mm_per_min, 400.0, kMm);
  EXPECT_NEAR(v.entry_feed_mm_per_min, 200.0, kMm);
}

TEST(MainTimeWorkedExample, PassCountsAndWidths) {
  const auto v = main_time_ok(main_time_worked_example());
  ASSERT_EQ(v.depth_passes_mm.size(), 3u);  // N2 = 3
  EXPECT_NEAR(v.depth_passes_mm[0], 2.0, kMm);
  EXPECT_NEAR(v.depth_passes_mm[1], 2.0, kMm);
  EXPECT_NEAR(v.depth_passes_mm[2], 1.0, kMm);
  ASSERT_EQ(v.lateral_passes.size(), 2u);  // N1 = 2
  EXPECT_NEAR(v.lateral_passes[0].width_mm, 45.0, kMm);
  EXPECT_NEAR(v.lateral_passes[1].width_mm, 35.0, kMm);
}

TEST(MainTimeWorkedExample, FirstLateralPass) {
  const auto v = main_time_ok(main_time_worked_example());
  ASSERT_EQ(v.lateral_passes.size(), 2u);
  const auto& p = v.lateral_passes[0];
  EXPECT_NEAR(p.strip_width_mm, 80.0, kMm);
  EXPECT_NEAR(p.axis_y_mm, 20.0, kMm);   // 45 - 25
  EXPECT_NEAR(p.offset_mm, -20.0, kMm);  // 20 - 40
  EXPECT_NEAR(p.engagement_length_mm, 25.0, kMm);
  EXPECT_NEAR(p.entry_length_mm, 27.0, kMm);
  EXPECT_NEAR(p.start.x_mm, 27.0, kMm);
  EXPECT_NEAR(p.start.y_mm, 20.0, kMm);
  EXPECT_NEAR(p.end.x_mm, 0.0, kMm);
  EXPECT_NEAR(p.end.y_mm, 20.0, kMm);
  EXPECT_NEAR(p.working_stroke_mm, 149.0, kMm);
  EXPECT_NEAR(p.entry_time_min, 0.135, kMin);
  EXPECT_NEAR(p.steady_time_min, 0.305, kMin);
  EXPECT_NEAR(p.time_min, 0.44, kMin);
}

TEST(MainTimeWorkedExample, SecondLateralPass) {
  const auto v = main_time_ok(main_time_worked_example());
  ASSERT_EQ(v.lateral_passes.size(), 2u);
  const auto& p = v.lateral_passes[1];
  const double end = std::sqrt(25.0 * 25.0 - 17.5 * 17.5);
  EXPECT_NEAR(end, 17.8535710714, kPrinted);
  EXPECT_NEAR(p.strip_width_mm, 35.0, kMm);
  EXPECT_NEAR(p.axis_y_mm, 62.5, kMm);
  EXPECT_NEAR(p.offset_mm, 0.0, kMm);
  EXPECT_NEAR(p.end.x_mm, 17.8535710714, kPrinted);
  EXPECT_NEAR(p.end.x_mm, end, kMm);
  EXPECT_NEAR(p.end.y_mm, 17.5, kMm);
  EXPECT_NEAR(p.engagement_length_mm, 7.1464289286, kPrinted);
  EXPECT_NEAR(p.engagement_length_mm, 25.0 - end, kMm);
  EXPECT_NEAR(p.entry_length_mm, 9.1464289286, kPrinted);
  EXPECT_NEAR(p.start.x_mm, 27.0, kMm);
  EXPECT_NEAR(p.start.y_mm, 17.5, kMm);
  EXPECT_NEAR(p.working_stroke_mm, 131.1464289286, kPrinted);
  EXPECT_NEAR(p.working_stroke_mm, 120.0 + 27.0 - end + 2.0, kMm);
  EXPECT_NEAR(p.entry_time_min, 0.0457321446, kPrinted);
  EXPECT_NEAR(p.entry_time_min, (27.0 - end) / 200.0, kMin);
  EXPECT_NEAR(p.steady_time_min, 0.305, kMin);
  EXPECT_NEAR(p.time_min, 0.3507321446, kPrinted);
}

TEST(MainTimeWorkedExample, Totals) {
  const auto v = main_time_ok(main_time_worked_example());
  EXPECT_NEAR(v.main_time_min, 2.3721964339, kPrinted);
  EXPECT_NEAR(v.entry_time_min, 0.5421964339, kPrinted);
  EXPECT_NEAR(v.steady_time_min, 1.83, kMin);
  const double end = std::sqrt(25.0 * 25.0 - 17.5 * 17.5);
  EXPECT_NEAR(v.main_time_min, 3.0 * (0.44 + (27.0 - end) / 200.0 + 0.305), kMin);
  expect_time_identities(v);
}

// ---- 7.1: numbers of passes
// ---------------------------------------------------------------------------

TEST(MainTimePasses, IntegerRatioGivesEqualPassesNotAZeroLastPass) {
  // Errata: the printed last pass H - t floor(H/t) is 0 for H = 6, t0 = 2; E25 gives 2, 2, 2.
  auto p = single_pass();
  p.allowance.depth_mm = 6.0;
  p.allowance.depth_of_cut_mm = 2.0;
  const auto v = main_time_ok(p);
  ASSERT_EQ(v.depth_passes_mm.size(), 3u);
  for (double d : v.depth_passes_mm) {
    EXPECT_NEAR(d, 2.0, kMm);
  }
  EXPECT_NEAR(v.main_time_min, 3.0 * v.lateral_passes.at(0).time_min, kMin);
}

TEST(MainTimePasses, LastDepthPassIsTheRemainder) {
  auto p = single_pass();
  p.allowance.depth_mm = 5.0;
  p.allowance.depth_of_cut_mm = 2.0;
  const auto v = main_time_ok(p);
  ASSERT_EQ(v.depth_passes_mm.size(), 3u);
  EXPECT_NEAR(v.depth_passes_mm[0], 2.0, kMm);
  EXPECT_NEAR(v.depth_passes_mm[1], 2.0, kMm);
  EXPECT_NEAR(v.depth_passes_mm[2], 1.0, kMm);
  // Depth of cut larger than the allowance: one pass of H.
  p.allowance.depth_mm = 1.5;
  const auto one = main_time_ok(p);
  ASSERT_EQ(one.depth_passes_mm.size(), 1u);
  EXPECT_NEAR(one.depth_passes_mm[0], 1.5, kMm);
}

TEST(MainTimePasses, CeilGuardAbsorbsDivisionRounding) {
  // 8.4 / 1.2 = 7.000000000000001 in doubles: ceil without the 1e-9 guard would give 8 passes with
  // a last pass of ~1e-15 mm. E24: ceil(H/t - 1e-9) = 7, the last pass H - 6 t0 = 1.2.
  ASSERT_GT(8.4 / 1.2, 7.0);
  auto p = single_pass();
  p.allowance.depth_mm = 8.4;
  p.allowance.depth_of_cut_mm = 1.2;
  const auto v = main_time_ok(p);
  ASSERT_EQ(v.depth_passes_mm.size(), 7u);
  EXPECT_NEAR(v.depth_passes_mm.back(), 8.4 - 6.0 * 1.2, kMm);
  EXPECT_NEAR(v.depth_passes_mm.back(), 1.2, kMm);

  // Lateral: 8.4 / 2.8 = 3.0000000000000004 -> N1 = 3 passes of 2.8 (D = 4, B = H1 = 8.4).
  ASSERT_GT(8.4 / 2.8, 3.0);
  MainTimeParams q = single_pass();
  q.cutter_diameter_mm = 4.0;
  q.entry = straight_contour(8.4);
  q.exit = straight_contour(8.4);
  q.offset_mm.reset();
  q.allowance = Allowance{8.4, 2.8, 2.0, 2.0};
  const auto w = main_time_ok(q);
  ASSERT_EQ(w.lateral_passes.size(), 3u);
  EXPECT_NEAR(w.lateral_passes[2].width_mm, 8.4 - 2.0 * 2.8, kMm);
  EXPECT_NEAR(w.lateral_passes[2].width_mm, 2.8, kMm);
}

TEST(MainTimePasses, LateralPlacementOfThreePasses) {
  // E27-E29: D = 4 (r = 2), B = H1 = 7, t = 3 -> widths 3, 3, 1; boundaries Y = 0, 3, 6;
  // strips [0, 7], [3, 7], [6, 7]; axes 3 - 2 = 1, 6 - 2 = 4, (6 + 7)/2 = 6.5;
  // offsets K_i = axis - strip centre = 1 - 3.5, 4 - 5, 6.5 - 6.5.
  MainTimeParams p;
  p.cutter_diameter_mm = 4.0;
  p.teeth = 2;
  p.speed = SpindleSpeed{1000.0};
  p.feed_per_tooth_mm = 0.05;
  p.length_mm = 50.0;
  p.entry = straight_contour(7.0);
  p.exit = straight_contour(7.0);
  p.allowance = Allowance{7.0, 3.0, 6.0, 2.0};
  const auto v = main_time_ok(p);
  ASSERT_EQ(v.lateral_passes.size(), 3u);
  ASSERT_EQ(v.depth_passes_mm.size(), 3u);
  const std::vector<double> widths{3.0, 3.0, 1.0};
  const std::vector<double> strips{7.0, 4.0, 1.0};
  const std::vector<double> axes{1.0, 4.0, 6.5};
  const std::vector<double> offsets{-2.5, -1.0, 0.0};
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& lp = v.lateral_passes[i];
    EXPECT_NEAR(lp.width_mm, widths[i], kMm) << "pass " << i + 1;
    EXPECT_NEAR(lp.strip_width_mm, strips[i], kMm) << "pass " << i + 1;
    EXPECT_NEAR(lp.axis_y_mm, axes[i], kMm) << "pass " << i + 1;
    EXPECT_NEAR(lp.offset_mm, offsets[i], kMm) << "pass " << i + 1;
    // Each pass is the one-pass problem on its strip (E29): E13 with B_i, K_i.
    const auto e = oracle::straight90_entry(4.0, strips[i], offsets[i], 2.0);
    const auto x = oracle::straight90_exit(4.0, strips[i], offsets[i]);
    ASSERT_TRUE(e && x);
    EXPECT_NEAR(lp.engagement_length_mm, e->engagement_mm, kMm) << "pass " << i + 1;
    EXPECT_NEAR(lp.entry_length_mm, 2.0 + e->engagement_mm, kMm) << "pass " << i + 1;
    EXPECT_NEAR(lp.start.x_mm, e->start_x_mm, kMm) << "pass " << i + 1;
    EXPECT_NEAR(lp.start.y_mm, strips[i] / 2.0 + offsets[i], kMm) << "pass " << i + 1;
    EXPECT_NEAR(lp.end.x_mm, x->end_x_mm, kMm) << "pass " << i + 1;
    EXPECT_NEAR(lp.end.y_mm, strips[i] / 2.0 + offsets[i], kMm) << "pass " << i + 1;
    EXPECT_NEAR(lp.working_stroke_mm, 50.0 + e->start_x_mm - x->end_x_mm + 2.0, kMm)
        << "pass " << i + 1;
  }
  // The last pass is S2: r = 2 > h = 0.5 -> X_k = sqrt(4 - 0.25).
  EXPECT_NEAR(v.lateral_passes[2].end.x_mm, std::sqrt(3.75), kMm);
  EXPECT_NEAR(v.lateral_passes[2].engagement_length_mm, 2.0 - std::sqrt(3.75), kMm);
  expect_time_identities(v);
  // S_m2 = 1000 * 2 * 0.05 = 100, S_m1 = 50.
  EXPECT_NEAR(v.main_time_min,
              3.0 * (2.0 * (4.0 / 50.0 + 52.0 / 100.0) + (4.0 - std::sqrt(3.75)) / 50.0 + 0.52),
              kMin);
}

// ---- 7.2: lateral placement with one pass; inclined and arc multi-pass
// ---------------------------------

TEST(MainTimeLateral, SinglePassUsesOffsetAndWholePart) {
  // E26: N1 = 1, K = -5: axis_y = h + K, strip = B, width = W (E2). D = 20, B = 50, v = 150 m/min,
  // L1 = 10, L_pod = 3, L_per = 2.5, f = 0.4, H = 4, t0 = 1.5 -> depths 1.5, 1.5, 1.
  MainTimeParams p = single_pass();
  p.speed = CuttingSpeed{150.0};
  p.entry_feed = EntryFeedFactor{0.4};
  p.length_mm = 120.0;
  p.extra_path_mm = 10.0;
  p.approach_mm = 3.0;
  p.overrun_mm = 2.5;
  p.entry = straight_contour(50.0);
  p.exit = straight_contour(50.0);
  p.offset_mm = -5.0;
  p.allowance = Allowance{20.0, 20.0, 4.0, 1.5};
  const auto v = main_time_ok(p);
  ASSERT_EQ(v.lateral_passes.size(), 1u);
  const auto& lp = v.lateral_passes[0];
  EXPECT_NEAR(lp.axis_y_mm, 20.0, kMm);
  EXPECT_NEAR(lp.offset_mm, -5.0, kMm);
  EXPECT_NEAR(lp.strip_width_mm, 50.0, kMm);
  EXPECT_NEAR(lp.width_mm, 20.0, kMm);
  EXPECT_NEAR(lp.engagement_length_mm, 10.0, kMm);
  EXPECT_NEAR(lp.entry_length_mm, 13.0, kMm);
  EXPECT_NEAR(lp.start.x_mm, 13.0, kMm);
  EXPECT_NEAR(lp.start.y_mm, 20.0, kMm);
  EXPECT_NEAR(lp.working_stroke_mm, 120.0 + 10.0 + 13.0 - 0.0 + 2.5, kMm);
  ASSERT_EQ(v.depth_passes_mm.size(), 3u);
  EXPECT_NEAR(v.depth_passes_mm[2], 1.0, kMm);
  const double n = 1000.0 * 150.0 / (std::numbers::pi * 20.0);
  EXPECT_NEAR(v.spindle_speed_rpm, n, kMm);
  EXPECT_NEAR(v.spindle_speed_rpm, 2387.3241463784, kPrinted);
  EXPECT_NEAR(v.main_time_min, 3.0 * (13.0 / (0.4 * n * 0.2) + 132.5 / (n * 0.2)), kMin);
  expect_time_identities(v);
}

TEST(MainTimeLateral, SinglePassOffsetDefaultsToZero) {
  MainTimeParams p = single_pass();
  p.offset_mm.reset();
  const auto v = main_time_ok(p);
  ASSERT_EQ(v.lateral_passes.size(), 1u);
  EXPECT_NEAR(v.lateral_passes[0].axis_y_mm, 30.0, kMm);
  EXPECT_NEAR(v.lateral_passes[0].offset_mm, 0.0, kMm);
  EXPECT_NEAR(v.lateral_passes[0].start.y_mm, 30.0, kMm);
  // P01 numbers: S_m2 = 200, S_m1 = 100, L_vr = 12, L_rx = 114 -> 0.12 + 0.51.
  EXPECT_NEAR(v.main_time_min, 0.63, kMin);
}

TEST(MainTimeLateral, SinglePassAllowanceNarrowerThanTheBandIsAccepted) {
  // N1 = 1: H1 is not compared with W; the pass still machines its steady band W = D.
  MainTimeParams p = single_pass();
  p.allowance = Allowance{10.0, 20.0, 2.0, 2.0};
  const auto v = main_time_ok(p);
  ASSERT_EQ(v.lateral_passes.size(), 1u);
  EXPECT_NEAR(v.lateral_passes[0].width_mm, 20.0, kMm);
}

TEST(MainTimeLateral, SinglePassWallExitHasNoOverrun) {
  MainTimeParams p = single_pass();
  p.exit = wall_contour(60.0);
  const auto v = main_time_ok(p);
  ASSERT_EQ(v.lateral_passes.size(), 1u);
  EXPECT_NEAR(v.lateral_passes[0].end.x_mm, 10.0, kMm);
  EXPECT_NEAR(v.lateral_passes[0].working_stroke_mm, 100.0 + 12.0 - 10.0, kMm);
  EXPECT_NEAR(v.main_time_min, 12.0 / 100.0 + 90.0 / 200.0, kMin);
}

TEST(MainTimeLateral, SinglePassOnAConvexArc) {
  // N1 = 1 on a convex arc R = 30 (B = 60): axis_y in the part frame = h + K; start/end Y from the
  // arc axis (= K); E18 case A and E19.
  MainTimeParams p = single_pass();
  p.length_mm = 150.0;
  p.entry = convex_contour(30.0);
  p.exit = convex_contour(30.0);
  const auto v = main_time_ok(p);
  ASSERT_EQ(v.lateral_passes.size(), 1u);
  const auto& lp = v.lateral_passes[0];
  EXPECT_NEAR(lp.axis_y_mm, 30.0, kMm);
  EXPECT_NEAR(lp.strip_width_mm, 60.0, kMm);
  EXPECT_NEAR(lp.start.y_mm, 0.0, kMm);
  EXPECT_NEAR(lp.start.x_mm, 12.0, kMm);
  const double end = 30.0 - std::sqrt(800.0);
  EXPECT_NEAR(lp.end.x_mm, end, kMm);
  EXPECT_NEAR(lp.engagement_length_mm, 40.0 - std::sqrt(800.0), kMm);
  EXPECT_NEAR(lp.working_stroke_mm, 150.0 + 12.0 - end + 2.0, kMm);
  expect_time_identities(v);
}

TEST(MainTimeLateral, InclinedEdgesShiftTheStripOrigins) {
  // Section 7.2 (inferred): each strip has its own corner; start/end are in the strip's frames and
  // L_i = L + Y_(i-1) (cot a_x - cot a). D = 20, B = H1 = 50, t = 20 -> widths 20, 20, 10;
  // strips [0, 50], [20, 50], [40, 50]; axes 10, 30, 45; K_i = -15, -5, 0.
  MainTimeParams p = single_pass();
  p.offset_mm.reset();
  p.length_mm = 200.0;
  p.entry = straight_contour(50.0, 60.0);
  p.exit = straight_contour(50.0, 75.0);
  p.allowance = Allowance{50.0, 20.0, 2.0, 2.0};
  const auto v = main_time_ok(p);
  ASSERT_EQ(v.lateral_passes.size(), 3u);
  const double lower[] = {0.0, 20.0, 40.0};
  const double strips[] = {50.0, 30.0, 10.0};
  const double axes[] = {10.0, 30.0, 45.0};
  const double offsets[] = {-15.0, -5.0, 0.0};
  const double widths[] = {20.0, 20.0, 10.0};
  const double cot_a = 1.0 / std::tan(60.0 * std::numbers::pi / 180.0);
  const double cot_ax = 1.0 / std::tan(75.0 * std::numbers::pi / 180.0);
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& lp = v.lateral_passes[i];
    EXPECT_NEAR(lp.width_mm, widths[i], kMm) << "pass " << i + 1;
    EXPECT_NEAR(lp.strip_width_mm, strips[i], kMm) << "pass " << i + 1;
    EXPECT_NEAR(lp.axis_y_mm, axes[i], kMm) << "pass " << i + 1;
    EXPECT_NEAR(lp.offset_mm, offsets[i], kMm) << "pass " << i + 1;
    const auto e = oracle::straight_entry(20.0, strips[i], offsets[i], 60.0, 2.0);
    const auto x = oracle::straight_exit(20.0, strips[i], offsets[i], 75.0);
    ASSERT_TRUE(e && x);
    EXPECT_NEAR(lp.engagement_length_mm, e->engagement_mm, kMm) << "pass " << i + 1;
    EXPECT_NEAR(lp.start.x_mm, e->start_x_mm, kMm) << "pass " << i + 1;
    EXPECT_NEAR(lp.start.y_mm, axes[i] - lower[i], kMm) << "pass " << i + 1;
    EXPECT_NEAR(lp.end.x_mm, x->end_x_mm, kMm) << "pass " << i + 1;
    EXPECT_NEAR(lp.end.y_mm, axes[i] - lower[i], kMm) << "pass " << i + 1;
    const double length_i = 200.0 + lower[i] * (cot_ax - cot_a);
    EXPECT_NEAR(lp.working_stroke_mm, length_i + e->start_x_mm - x->end_x_mm + 2.0, kMm)
        << "pass " << i + 1;
  }
  expect_time_identities(v);
}

TEST(MainTimeLateral, ConvexArcWithSeveralPassesUsesThePartContour) {
  // Section 7.2 (inferred, no reference case): arcs with N1 > 1 apply E10/E11 to the part's arc
  // over [y_ax - r, y_ax + r] intersected with [Y_(i-1) - h, h]; start/end Y from the arc axis. R =
  // 30 (B = 60), D = 20, H1 = 60, t = 20: axes (part frame) 10, 30, 50 -> y_ax = -20, 0, 20.
  MainTimeParams p = single_pass();
  p.offset_mm.reset();
  p.length_mm = 150.0;
  p.entry = convex_contour(30.0);
  p.exit = convex_contour(30.0);
  p.allowance = Allowance{60.0, 20.0, 2.0, 2.0};
  const auto v = main_time_ok(p);
  ASSERT_EQ(v.lateral_passes.size(), 3u);
  const double lower[] = {0.0, 20.0, 40.0};
  const double axes[] = {10.0, 30.0, 50.0};
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& lp = v.lateral_passes[i];
    const double y_ax = axes[i] - 30.0;
    EXPECT_NEAR(lp.axis_y_mm, axes[i], kMm) << "pass " << i + 1;
    EXPECT_NEAR(lp.strip_width_mm, 60.0 - lower[i], kMm) << "pass " << i + 1;
    EXPECT_NEAR(lp.offset_mm, axes[i] - (lower[i] + 60.0) / 2.0, kMm) << "pass " << i + 1;
    EXPECT_NEAR(lp.width_mm, 20.0, kMm) << "pass " << i + 1;
    const auto e = oracle::convex_entry_on(20.0, 30.0, y_ax, lower[i] - 30.0, 30.0, 2.0);
    const auto x = oracle::convex_exit_on(20.0, 30.0, y_ax, lower[i] - 30.0, 30.0);
    ASSERT_TRUE(e && x);
    EXPECT_NEAR(lp.engagement_length_mm, e->engagement_mm, kMm) << "pass " << i + 1;
    EXPECT_NEAR(lp.start.x_mm, e->start_x_mm, kMm) << "pass " << i + 1;
    EXPECT_NEAR(lp.start.y_mm, y_ax, kMm) << "pass " << i + 1;
    EXPECT_NEAR(lp.end.x_mm, x->end_x_mm, kMm) << "pass " << i + 1;
    EXPECT_NEAR(lp.end.y_mm, y_ax, kMm) << "pass " << i + 1;
    EXPECT_NEAR(lp.working_stroke_mm, 150.0 + e->start_x_mm - x->end_x_mm + 2.0, kMm)
        << "pass " << i + 1;
  }
  expect_time_identities(v);
}

// ---- 7.3: speed and feeds
// ---------------------------------------------------------------------------

TEST(MainTimeFeeds, CuttingSpeedGivesSpindleSpeedE30) {
  MainTimeParams p = single_pass();
  p.speed = CuttingSpeed{150.0};
  const auto v = main_time_ok(p);
  const double n = 1000.0 * 150.0 / (std::numbers::pi * 20.0);  // not rounded
  EXPECT_NEAR(v.spindle_speed_rpm, n, kMm);
  EXPECT_NEAR(v.feed_per_rev_mm, 0.05 * 4.0, kMm);
  EXPECT_NEAR(v.feed_mm_per_min, n * 4.0 * 0.05, kMm);
  EXPECT_NEAR(v.entry_feed_mm_per_min, 0.5 * n * 4.0 * 0.05, kMm);
}

TEST(MainTimeFeeds, SpindleSpeedWithEntryFeedFactor) {
  // P-FEEDS: n = 2500, z = 3, S_z = 0.08 -> S_o = 0.24, S_m2 = 600; f = 0.3 -> S_m1 = 180.
  MainTimeParams p = single_pass();
  p.cutter_diameter_mm = 16.0;
  p.teeth = 3;
  p.speed = SpindleSpeed{2500.0};
  p.feed_per_tooth_mm = 0.08;
  p.entry_feed = EntryFeedFactor{0.3};
  p.allowance = Allowance{16.0, 16.0, 2.0, 2.0};
  const auto v = main_time_ok(p);
  EXPECT_NEAR(v.spindle_speed_rpm, 2500.0, kMm);
  EXPECT_NEAR(v.feed_per_rev_mm, 0.24, kMm);
  EXPECT_NEAR(v.feed_mm_per_min, 600.0, kMm);
  EXPECT_NEAR(v.entry_feed_mm_per_min, 180.0, kMm);
  expect_time_identities(v);
}

TEST(MainTimeFeeds, DefaultEntryFeedFactorIsOneHalf) {
  MainTimeParams p = single_pass();  // entry_feed left at its default
  const auto v = main_time_ok(p);
  EXPECT_NEAR(v.feed_mm_per_min, 200.0, kMm);
  EXPECT_NEAR(v.entry_feed_mm_per_min, 100.0, kMm);
}

TEST(MainTimeFeeds, EntryFeedPerToothWithCuttingSpeed) {
  // S_m1 = n z S_z1 (E33): v = 200, D = 32, z = 3, S_z = 0.08, S_z1 = 0.03; convex arc R = 25, K
  // = 6.
  MainTimeParams p = single_pass();
  p.cutter_diameter_mm = 32.0;
  p.teeth = 3;
  p.speed = CuttingSpeed{200.0};
  p.feed_per_tooth_mm = 0.08;
  p.entry_feed = EntryFeedPerTooth{0.03};
  p.length_mm = 150.0;
  p.entry = convex_contour(25.0);
  p.exit = convex_contour(25.0);
  p.offset_mm = 6.0;
  p.allowance = Allowance{32.0, 32.0, 2.0, 2.0};
  const auto v = main_time_ok(p);
  const double n = 1000.0 * 200.0 / (std::numbers::pi * 32.0);
  EXPECT_NEAR(v.spindle_speed_rpm, n, kMm);
  EXPECT_NEAR(v.spindle_speed_rpm, 1989.4367886487, kPrinted);
  EXPECT_NEAR(v.feed_per_rev_mm, 0.24, kMm);
  EXPECT_NEAR(v.feed_mm_per_min, n * 0.24, kMm);
  EXPECT_NEAR(v.entry_feed_mm_per_min, n * 3.0 * 0.03, kMm);
  EXPECT_NEAR(v.entry_feed_mm_per_min, 179.0493109784, kPrinted);
  ASSERT_EQ(v.lateral_passes.size(), 1u);
  const auto e = oracle::convex_full_entry(32.0, 25.0, 6.0, 2.0);
  ASSERT_TRUE(e.has_value());
  EXPECT_NEAR(v.lateral_passes[0].engagement_length_mm, e->engagement_mm, kMm);
  EXPECT_NEAR(v.lateral_passes[0].axis_y_mm, 31.0, kMm);
  expect_time_identities(v);
}

TEST(MainTimeFeeds, EntryFeedPerToothEqualToFeedPerToothIsAccepted) {
  MainTimeParams p = single_pass();
  p.entry_feed = EntryFeedPerTooth{0.05};
  const auto v = main_time_ok(p);
  EXPECT_NEAR(v.entry_feed_mm_per_min, v.feed_mm_per_min, kMm);
}

// ---- 7.4: times
// ---------------------------------------------------------------------------------------

TEST(MainTimeTimes, TotalsAreDepthPassesTimesTheLateralSum) {
  // N1 = 3 lateral x N2 = 5 depth passes on an inclined part.
  MainTimeParams p = single_pass();
  p.offset_mm.reset();
  p.entry = straight_contour(50.0, 70.0);
  p.exit = straight_contour(50.0, 100.0);
  p.allowance = Allowance{50.0, 20.0, 9.0, 2.0};
  const auto v = main_time_ok(p);
  ASSERT_EQ(v.lateral_passes.size(), 3u);
  ASSERT_EQ(v.depth_passes_mm.size(), 5u);
  EXPECT_NEAR(v.depth_passes_mm[4], 1.0, kMm);
  double sum = 0.0;
  for (const auto& lp : v.lateral_passes) {
    sum += lp.time_min;
  }
  EXPECT_NEAR(v.main_time_min, 5.0 * sum, kMin);
  expect_time_identities(v);
}

TEST(MainTimePasses, ZeroOffsetWithSeveralPassesIsTheSameAsNone) {
  // 0 is offset_mm's documented default: sent explicitly it changes nothing.
  MainTimeParams with_zero = main_time_worked_example();
  with_zero.offset_mm = 0.0;
  MainTimeParams without = main_time_worked_example();
  without.offset_mm.reset();
  const auto a = main_time_ok(with_zero);
  const auto b = main_time_ok(without);
  ASSERT_EQ(a.lateral_passes.size(), b.lateral_passes.size());
  EXPECT_GT(a.lateral_passes.size(), 1u);
  EXPECT_DOUBLE_EQ(a.main_time_min, b.main_time_min);
}

// ---- section 8: errors
// ------------------------------------------------------------------------------

TEST(MainTimeErrors, OffsetWithSeveralPasses) {
  MainTimeParams p = main_time_worked_example();
  p.offset_mm = 1.0;
  expect_error(p, ErrorCode::offset_with_several_passes, "offset with N1 = 2");
}

TEST(MainTimeErrors, AllowanceWiderThanPart) {
  // N1 = 1 (t >= H1), H1 = 70 > B = 60.
  MainTimeParams p = single_pass();
  p.cutter_diameter_mm = 80.0;
  p.allowance = Allowance{70.0, 70.0, 2.0, 2.0};
  expect_error(p, ErrorCode::allowance_wider_than_part, "H1 = 70 > B = 60");
}

TEST(MainTimeErrors, AllowanceNotFullWidthWithSeveralPasses) {
  // N1 = ceil(50 / 30) = 2 but H1 = 50 != B = 80.
  MainTimeParams p = main_time_worked_example();
  p.cutter_diameter_mm = 40.0;
  p.allowance = Allowance{50.0, 30.0, 2.0, 2.0};
  expect_error(p, ErrorCode::allowance_not_full_width, "H1 = 50, B = 80, N1 = 2");
}

TEST(MainTimeErrors, AllowanceWidthComparedWithRelativeTolerance) {
  MainTimeParams p = main_time_worked_example();
  p.allowance.width_mm = 80.0 * (1.0 + 1e-12);
  const auto ok = compute_main_time(p);
  EXPECT_TRUE(ok.ok()) << outcome(ok);
  p.allowance.width_mm = 80.0 * (1.0 - 1e-6);
  expect_error(p, ErrorCode::allowance_not_full_width, "H1 = B (1 - 1e-6)");
}

TEST(MainTimeErrors, WidthOfCutExceedsDiameter) {
  MainTimeParams p = main_time_worked_example();
  p.cutter_diameter_mm = 40.0;  // t = 45 > D = 40, N1 = 2
  expect_error(p, ErrorCode::width_of_cut_exceeds_diameter, "t = 45 > D = 40, N1 = 2");
  MainTimeParams q = single_pass();  // checked whatever N1
  q.allowance = Allowance{20.0, 25.0, 2.0, 2.0};
  expect_error(q, ErrorCode::width_of_cut_exceeds_diameter, "t = 25 > D = 20, N1 = 1");
}

TEST(MainTimeErrors, EntryFeedExceedsFeed) {
  MainTimeParams p = single_pass();
  p.entry_feed = EntryFeedPerTooth{0.06};  // > S_z = 0.05
  expect_error(p, ErrorCode::entry_feed_exceeds_feed, "S_z1 = 0.06 > S_z = 0.05");
}

TEST(MainTimeErrors, ExitWidthMustEqualPartWidth) {
  MainTimeParams p = single_pass();
  p.exit = straight_contour(70.0);
  expect_error(p, ErrorCode::exit_width_mismatch, "exit 70 vs part 60");
}

TEST(MainTimeErrors, EntryLengthErrorsPropagate) {
  MainTimeParams p = single_pass();
  p.offset_mm = 40.0;  // |K| = h + r: tangency
  expect_error(p, ErrorCode::no_contact, "tangent single pass");
  MainTimeParams q = single_pass();
  q.exit = straight_contour(60.0, 150.0);  // exit far downstream of its origin
  q.length_mm = 5.0;
  expect_error(q, ErrorCode::stroke_shorter_than_entry, "short stroke");
}
