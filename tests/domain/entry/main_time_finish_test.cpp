// Unit tests: equal passes and the finishing depth level (spec entry-and-main-time.md section 15,
// E37-E41), on the worked example of section 14.

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "domain/entry/entry_test_support.h"
#include "domain/entry/main_time.h"

namespace {

using cutcalc::domain::ErrorCode;
using cutcalc::domain::entry::Allowance;
using cutcalc::domain::entry::compute_main_time;
using cutcalc::domain::entry::CuttingSpeed;
using cutcalc::domain::entry::EntryFeedFactor;
using cutcalc::domain::entry::EntryFeedPerTooth;
using cutcalc::domain::entry::Finish;
using cutcalc::domain::entry::MainTimeParams;
using cutcalc::domain::entry::MainTimeResult;
using cutcalc::domain::entry::PassSplit;
using cutcalc::domain::entry::SpindleSpeed;
using cutcalc::test::main_time_ok;
using cutcalc::test::main_time_worked_example;
using cutcalc::test::outcome;
using cutcalc::test::straight_contour;

using cutcalc::test::kMin;
using cutcalc::test::kMm;

// The finishing level of the spec's example: t_f = 0.5, S_zf = 0.05.
Finish half_mm_finish() { return Finish{0.5, 0.05, std::nullopt}; }

void expect_sizes(const std::vector<double>& got, const std::vector<double>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(got[i], want[i], kMm) << i;
}

// E37: N1 = ceil(80/45) = 2 widths 40, 40; N2 = ceil(5/2) = 3 depths 5/3.
TEST(MainTimeEqualSplit, EqualWidthsAndDepthsE37) {
  MainTimeParams p = main_time_worked_example();
  p.pass_split = PassSplit::equal;
  const MainTimeResult v = main_time_ok(p);
  expect_sizes(v.depth_passes_mm, {5.0 / 3.0, 5.0 / 3.0, 5.0 / 3.0});
  ASSERT_EQ(v.lateral_passes.size(), 2U);
  EXPECT_NEAR(v.lateral_passes[0].width_mm, 40.0, kMm);
  EXPECT_NEAR(v.lateral_passes[1].width_mm, 40.0, kMm);
}

// E38: Y_1 = t_e = 40, axis Y_1 - r = 15, K_1 = 15 - 40 = -25 (S1); pass 2 strip [40, 80], centred
// (K 0, h = 20 < r = 25: S2, L_vr1 = r - sqrt(r^2 - h^2) = 10); T_o = 3 (0.44 + 0.365) = 2.415.
TEST(MainTimeEqualSplit, PlacementAndMainTimeFollowTheEqualWidthsE38) {
  MainTimeParams p = main_time_worked_example();
  p.pass_split = PassSplit::equal;
  const MainTimeResult v = main_time_ok(p);
  ASSERT_EQ(v.lateral_passes.size(), 2U);
  EXPECT_NEAR(v.lateral_passes[0].axis_y_mm, 15.0, kMm);
  EXPECT_NEAR(v.lateral_passes[0].offset_mm, -25.0, kMm);
  EXPECT_NEAR(v.lateral_passes[0].engagement_length_mm, 25.0, kMm);
  EXPECT_NEAR(v.lateral_passes[0].lower_boundary_mm, 0.0, kMm);
  EXPECT_NEAR(v.lateral_passes[1].axis_y_mm, 60.0, kMm);
  EXPECT_NEAR(v.lateral_passes[1].strip_width_mm, 40.0, kMm);
  EXPECT_NEAR(v.lateral_passes[1].lower_boundary_mm, 40.0, kMm);
  EXPECT_NEAR(v.lateral_passes[1].engagement_length_mm, 25.0 - 15.0, kMm);
  EXPECT_NEAR(v.lateral_passes[1].working_stroke_mm, 120.0 + 27.0 - 15.0 + 2.0, kMm);
  EXPECT_NEAR(v.main_time_min, 3.0 * (0.44 + (12.0 / 200.0 + 122.0 / 400.0)), kMin);
  EXPECT_FALSE(v.finish.has_value());
}

// E37: an integer ratio gives the same passes either way.
TEST(MainTimeEqualSplit, IntegerRatioIsTheSameAsLastSmaller) {
  MainTimeParams p = main_time_worked_example();
  p.allowance = Allowance{80.0, 40.0, 6.0, 2.0};
  const MainTimeResult last_smaller = main_time_ok(p);
  p.pass_split = PassSplit::equal;
  const MainTimeResult equal = main_time_ok(p);
  expect_sizes(equal.depth_passes_mm, last_smaller.depth_passes_mm);
  EXPECT_NEAR(equal.main_time_min, last_smaller.main_time_min, kMin);
}

// E39: H_r = 4.5 split by E25 with t0 = 2: 2, 2, 0.5, then t_f = 0.5.
TEST(MainTimeFinish, RoughingDepthSplitThenFinishingDepthE39) {
  MainTimeParams p = main_time_worked_example();
  p.finish = half_mm_finish();
  const MainTimeResult v = main_time_ok(p);
  expect_sizes(v.depth_passes_mm, {2.0, 2.0, 0.5, 0.5});
  ASSERT_TRUE(v.finish.has_value());
  EXPECT_NEAR(v.finish->depth_mm, 0.5, kMm);
}

// E37 + E39: H_r = 4.5 in N2r = 3 equal levels of 1.5.
TEST(MainTimeFinish, EqualRoughingLevelsE39) {
  MainTimeParams p = main_time_worked_example();
  p.pass_split = PassSplit::equal;
  p.finish = half_mm_finish();
  expect_sizes(main_time_ok(p).depth_passes_mm, {1.5, 1.5, 1.5, 0.5});
}

// E40 without a finish speed: n_f = n, S_m2f = 1000 x 4 x 0.05 = 200, S_m1f = 0.5 x 200.
TEST(MainTimeFinish, FinishingFeedsAtTheRoughingSpeedE40) {
  MainTimeParams p = main_time_worked_example();
  p.finish = half_mm_finish();
  const MainTimeResult v = main_time_ok(p);
  ASSERT_TRUE(v.finish.has_value());
  EXPECT_NEAR(v.finish->spindle_speed_rpm, 1000.0, kMm);
  EXPECT_NEAR(v.finish->feed_per_rev_mm, 0.2, kMm);
  EXPECT_NEAR(v.finish->feed_mm_per_min, 200.0, kMm);
  EXPECT_NEAR(v.finish->entry_feed_mm_per_min, 100.0, kMm);
  // The roughing feeds are unchanged.
  EXPECT_NEAR(v.feed_mm_per_min, 400.0, kMm);
}

// E40: n_f from its own rpm, or from v_f by E30; S_m1f from S_z1 when given.
TEST(MainTimeFinish, FinishingSpeedFromRpmOrCuttingSpeedE40) {
  MainTimeParams p = main_time_worked_example();
  p.finish = half_mm_finish();
  p.finish->speed = SpindleSpeed{1500.0};
  MainTimeResult v = main_time_ok(p);
  ASSERT_TRUE(v.finish.has_value());
  EXPECT_NEAR(v.finish->feed_mm_per_min, 300.0, kMm);
  EXPECT_NEAR(v.finish->entry_feed_mm_per_min, 150.0, kMm);

  p.finish->speed = CuttingSpeed{200.0};
  p.entry_feed = EntryFeedPerTooth{0.02};
  v = main_time_ok(p);
  ASSERT_TRUE(v.finish.has_value());
  const double n_f = 1000.0 * 200.0 / (std::numbers::pi * 50.0);
  EXPECT_NEAR(v.finish->spindle_speed_rpm, n_f, kMm);
  EXPECT_NEAR(v.finish->feed_mm_per_min, n_f * 4.0 * 0.05, kMm);
  EXPECT_NEAR(v.finish->entry_feed_mm_per_min, n_f * 4.0 * 0.02, kMm);
  EXPECT_NEAR(v.entry_feed_mm_per_min, 1000.0 * 4.0 * 0.02, kMm);  // S_m1 = n z S_z1
}

// E41: T_o = N2r sum t_i + sum t_i,f = 3 x 0.7907321446 + 1.5814642893 = 3.95366 (section 15).
TEST(MainTimeFinish, MainTimeAddsTheFinishingLevelAtItsFeedsE41) {
  MainTimeParams p = main_time_worked_example();
  const MainTimeResult roughing_only = main_time_ok(p);
  p.finish = half_mm_finish();
  const MainTimeResult v = main_time_ok(p);
  ASSERT_TRUE(v.finish.has_value());
  ASSERT_EQ(v.finish->lateral_passes.size(), v.lateral_passes.size());
  double level_time = 0.0;
  for (std::size_t i = 0; i < v.lateral_passes.size(); ++i) {
    const auto& pass = v.lateral_passes[i];
    const auto& times = v.finish->lateral_passes[i];
    EXPECT_NEAR(times.entry_time_min, pass.entry_length_mm / 100.0, kMin) << i;
    EXPECT_NEAR(times.steady_time_min, (pass.working_stroke_mm - pass.entry_length_mm) / 200.0,
                kMin)
        << i;
    level_time += pass.time_min;
  }
  // The lateral passes' own times stay those of one roughing traverse.
  EXPECT_NEAR(level_time, roughing_only.main_time_min / 3.0, kMin);
  EXPECT_NEAR(v.finish->time_min, 2.0 * level_time, kMin);  // half the feed: twice the time
  EXPECT_NEAR(v.main_time_min, 3.0 * level_time + v.finish->time_min, kMin);
  EXPECT_NEAR(v.main_time_min, 3.9536607232, 1e-9);
  EXPECT_NEAR(v.entry_time_min + v.steady_time_min, v.main_time_min, kMin);
  EXPECT_NEAR(v.entry_time_min, 3.0 * (0.135 + 0.0457321446) + v.finish->entry_time_min, 1e-9);
}

// Section 15 worked example: equal passes and the finish: T_o = 3 x 0.805 + 1.61 = 4.025.
TEST(MainTimeFinish, EqualSplitWithFinishE37E41) {
  MainTimeParams p = main_time_worked_example();
  p.pass_split = PassSplit::equal;
  p.finish = half_mm_finish();
  const MainTimeResult v = main_time_ok(p);
  EXPECT_NEAR(v.main_time_min, 3.0 * (0.44 + 0.365) + 2.0 * (0.44 + 0.365), kMin);
}

// E39: at least one roughing level (t_f < H); t_f = H is refused.
TEST(MainTimeFinish, FinishAsDeepAsTheAllowanceIsRefused) {
  MainTimeParams p = main_time_worked_example();
  p.finish = Finish{5.0, 0.05, std::nullopt};
  const auto res = compute_main_time(p);
  ASSERT_FALSE(res.ok());
  EXPECT_EQ(res.error().code, ErrorCode::finish_depth_not_below_depth) << outcome(res);
}

// H - t_f <= t0: one roughing level.
TEST(MainTimeFinish, ThinRoughingAllowanceGivesOneRoughingLevel) {
  MainTimeParams p = main_time_worked_example();
  p.allowance.depth_mm = 2.5;
  p.finish = half_mm_finish();
  expect_sizes(main_time_ok(p).depth_passes_mm, {2.0, 0.5});
}

// Section 15 validation: S_z1 > S_zf would make the finishing entry faster than its steady cut.
TEST(MainTimeFinish, EntryFeedPerToothAboveTheFinishingFeedIsRefused) {
  MainTimeParams p = main_time_worked_example();
  p.entry_feed = EntryFeedPerTooth{0.06};
  p.finish = half_mm_finish();
  const auto res = compute_main_time(p);
  ASSERT_FALSE(res.ok());
  EXPECT_EQ(res.error().code, ErrorCode::entry_feed_exceeds_feed) << outcome(res);
}

}  // namespace
