// The whole flat (lathe-flat.md F1-F21): d from each of t, b, d, s; the polygon's face width and
// sharp corners; steps or a tolerance; layers; the clear X; blocks and times; the shortest block
// and the block-rate limit with its warning at the boundary; the refusals at their boundaries.

#include "domain/lathe_flat/lathe_flat.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "domain/lathe_flat/flatness.h"
#include "domain/lathe_flat/lathe_flat_settings.h"

namespace cutcalc::domain::lathe_flat {
namespace {

using program::WarningCode;

using settings::paper_flat;

LatheFlatResult computed(const LatheFlatParams& p) {
  const auto result = compute_lathe_flat(p);
  EXPECT_TRUE(result.ok()) << (result.ok() ? "" : error_code_name(result.error().code));
  return result.ok() ? result.value() : LatheFlatResult{};
}

ErrorCode refusal(const LatheFlatParams& p) {
  const auto result = compute_lathe_flat(p);
  EXPECT_FALSE(result.ok());
  return result.ok() ? ErrorCode::not_converged : result.error().code;
}

std::vector<WarningCode> warning_codes(const LatheFlatParams& p) {
  std::vector<WarningCode> codes;
  for (const auto& warning : computed(p).warnings) codes.push_back(warning.code);
  return codes;
}

TEST(LatheFlat, EachOfDepthWidthAxisDistanceAndAcrossFlatsGivesTheSameFlat) {
  // F1: t = 1, b = 2 sqrt(31), d = 15, s = 30 (with two flats) on D32.
  std::vector<LatheFlatParams> ways(4, paper_flat());
  ways[1].flat_depth_mm.reset();
  ways[1].flat_width_mm = 2.0 * std::sqrt(31.0);
  ways[2].flat_depth_mm.reset();
  ways[2].axis_distance_mm = 15.0;
  ways[3].flat_depth_mm.reset();
  ways[3].across_flats_mm = 30.0;
  for (LatheFlatParams& p : ways) p.flats = 2;
  for (const LatheFlatParams& p : ways) {
    const LatheFlatResult r = computed(p);
    EXPECT_NEAR(r.axis_distance_mm, 15.0, 1e-12);
    EXPECT_NEAR(r.flat_depth_mm, 1.0, 1e-12);
    EXPECT_NEAR(r.across_flats_mm, 30.0, 1e-12);
    EXPECT_NEAR(r.flat_width_mm, 11.135529, 0.5e-6);
    EXPECT_NEAR(r.engagement_half_angle_deg, 20.364135, 0.5e-6);
  }
}

TEST(LatheFlat, WidthGivesTheDistanceWithoutCancellation) {
  // F1: d = sqrt((R2 - b/2)(R2 + b/2)) for a flat narrow against the part.
  LatheFlatParams p = paper_flat();
  p.flat_depth_mm.reset();
  p.flat_width_mm = 7.0;  // F-E1: 7 mm wide on D32 is 0.3875 mm deep
  EXPECT_NEAR(computed(p).flat_depth_mm, 16.0 - std::sqrt(16.0 * 16.0 - 3.5 * 3.5), 1e-12);
  EXPECT_NEAR(computed(p).flat_depth_mm, 0.3875, 0.5e-4);
}

TEST(LatheFlat, OneOrTwoFlatsKeepTheWholeWidthAndNoSharpCorners) {
  for (const int flats : {1, 2}) {
    LatheFlatParams p = paper_flat();
    p.flats = flats;
    p.flat_depth_mm = 15.0;  // alpha_e = 86 deg: sharp for any polygon, not for these
    const LatheFlatResult r = computed(p);
    EXPECT_EQ(r.face_width_mm, r.flat_width_mm);
    EXPECT_FALSE(r.sharp_corners);
  }
}

TEST(LatheFlat, PolygonFaceWidthAndSharpCornersEitherSideOfTheBoundary) {
  // F4, hexagon on D32: the corners meet on the cylinder at d = R2 cos 30 deg.
  LatheFlatParams p = paper_flat();
  p.flat_depth_mm.reset();
  p.flats = 6;
  const double boundary = 16.0 * std::cos(std::numbers::pi / 6.0);
  p.axis_distance_mm = boundary + 1e-9;  // shallower: cylindrical lands remain
  LatheFlatResult r = computed(p);
  EXPECT_FALSE(r.sharp_corners);
  EXPECT_NEAR(r.face_width_mm, r.flat_width_mm, 1e-12);
  EXPECT_LT(r.flat_width_mm, 2.0 * *p.axis_distance_mm * std::tan(std::numbers::pi / 6.0));
  p.axis_distance_mm = boundary - 1e-9;  // deeper: the flats meet
  r = computed(p);
  EXPECT_TRUE(r.sharp_corners);
  EXPECT_NEAR(r.face_width_mm, 2.0 * *p.axis_distance_mm * std::tan(std::numbers::pi / 6.0), 1e-12);
  EXPECT_LT(r.face_width_mm, r.flat_width_mm);
  // Well inside: a square on D32 with s = 20: w = s, b = 2 sqrt(16^2 - 10^2).
  p.flats = 4;
  p.axis_distance_mm = 10.0;
  r = computed(p);
  EXPECT_TRUE(r.sharp_corners);
  EXPECT_NEAR(r.face_width_mm, 20.0, 1e-12);
  EXPECT_NEAR(r.flat_width_mm, 2.0 * std::sqrt(156.0), 1e-12);
}

TEST(LatheFlat, StepsGivenOrFromTheTolerance) {
  LatheFlatParams p = paper_flat();
  LatheFlatResult r = computed(p);
  EXPECT_EQ(r.steps, 10);
  EXPECT_FALSE(r.steps_for_tolerance.has_value());
  EXPECT_NEAR(r.flatness_error_mm * 1000.0, 2.9531, 0.5e-4);
  EXPECT_NEAR(r.flatness_error_estimate_mm * 1000.0, 3.021, 0.5e-3);
  EXPECT_EQ(r.steps_table.size(), 21U);
  // A tolerance alone gives N by F16; both: steps are used and the tolerance's N is reported.
  p.steps.reset();
  p.flatness_tolerance_mm = 0.003;  // error(10) = 2.953 um meets it; error(9) = 3.6 um does not
  r = computed(p);
  EXPECT_EQ(r.steps, 10);
  EXPECT_EQ(r.steps_for_tolerance, 10);
  p.steps = 4;
  r = computed(p);
  EXPECT_EQ(r.steps, 4);
  EXPECT_EQ(r.steps_for_tolerance, 10);
  EXPECT_EQ(r.steps_table.size(), 9U);
}

TEST(LatheFlat, LayersAreEqualWithTheLastExactlyTheDepth) {
  // F17: L = ceil(t/a - 1e-9): t = 2.1, a = 0.3 gives 7.000000000000001 in doubles, 7 layers.
  LatheFlatParams p = paper_flat();
  p.flat_depth_mm = 2.1;
  p.layer_depth_mm = 0.3;
  LatheFlatResult r = computed(p);
  EXPECT_EQ(r.layers, 7);
  ASSERT_EQ(r.layer_depths_mm.size(), 7U);
  for (int j = 1; j <= 7; ++j) {
    EXPECT_NEAR(r.layer_depths_mm[static_cast<std::size_t>(j - 1)], j * 2.1 / 7.0, 1e-15) << j;
  }
  EXPECT_EQ(r.layer_depths_mm.back(), r.flat_depth_mm);
  // t = 2.4 arrives as R2 - d = 2.4000000000000004: t/a = 6.000000000000001, still 6 layers.
  p.flat_depth_mm = 2.4;
  p.layer_depth_mm = 0.4;
  EXPECT_EQ(computed(p).layers, 6);
  p.flat_depth_mm = 2.1;
  // A remainder makes a layer more: a = 0.29 -> 8 equal layers.
  p.layer_depth_mm = 0.29;
  EXPECT_EQ(computed(p).layers, 8);
  // Default a = t, and a > t: one layer.
  p.layer_depth_mm.reset();
  EXPECT_EQ(computed(p).layers, 1);
  p.layer_depth_mm = 5.0;
  r = computed(p);
  EXPECT_EQ(r.layers, 1);
  EXPECT_EQ(r.layer_depths_mm, std::vector<double>{r.flat_depth_mm});
}

TEST(LatheFlat, ClearXIsTheDeepestLayerStartPlusTheClearance) {
  // F18: X_c = R2 + R R2/d + c of the final layer.
  LatheFlatParams p = paper_flat();
  p.tool_radius_mm = 5.0;
  p.clearance_mm = 2.5;
  p.flat_depth_mm = 3.0;
  p.layer_depth_mm = 1.0;
  const LatheFlatResult r = computed(p);
  EXPECT_NEAR(r.clear_x_mm, 16.0 + 5.0 * 16.0 / 13.0 + 2.5, 1e-12);
  EXPECT_GE(r.clear_x_mm, 16.0 + 5.0 + 2.5);
  EXPECT_NEAR(computed(paper_flat()).clear_x_mm, 17.0, 1e-12);  // point tool, c = 1
}

TEST(LatheFlat, WorkedExampleBlocksAndTimes) {
  // Section 9: 20 blocks; cut b/f = 0.111355 min, approach 1 mm at f = 0.01 min.
  const LatheFlatResult r = computed(paper_flat());
  EXPECT_EQ(r.cut_blocks, 20);
  EXPECT_NEAR(r.cut_time_min, 0.111355, 0.5e-6);
  EXPECT_NEAR(r.cut_time_min, 2.0 * std::sqrt(31.0) / 100.0, 1e-14);
  EXPECT_NEAR(r.approach_time_min, 0.01, 1e-14);
  EXPECT_NEAR(r.machining_time_min, 0.121355, 0.5e-6);
  EXPECT_NEAR(r.x_travel_mm, 1.0, 1e-12);
}

TEST(LatheFlat, BlocksAndTimesSumOverFlatsAndLayers) {
  // F19 with m = 3, L = 2, R = 4, N = 5: the cut time is the sum of the chords over the feed.
  LatheFlatParams p = paper_flat();
  p.flats = 3;
  p.tool_radius_mm = 4.0;
  p.steps = 5;
  p.flat_depth_mm = 2.0;
  p.layer_depth_mm = 1.0;
  p.feed_mm_per_min = 250.0;
  p.clearance_mm = 1.5;
  const LatheFlatResult r = computed(p);
  EXPECT_EQ(r.cut_blocks, 2 * 5 * 3 * 2);
  double cut = 0.0;
  double approach = 0.0;
  for (const double t_j : {1.0, 2.0}) {
    const double d_j = 16.0 - t_j;
    const double half_chord = std::sqrt(16.0 * 16.0 - d_j * d_j);
    cut += 3.0 * 2.0 * (d_j + 4.0) * half_chord / d_j / 250.0;
    approach += 3.0 * (r.clear_x_mm - (d_j + 4.0) * 16.0 / d_j) / 250.0;
  }
  EXPECT_NEAR(r.cut_time_min, cut, 1e-13);
  EXPECT_NEAR(r.approach_time_min, approach, 1e-13);
  EXPECT_NEAR(r.machining_time_min, cut + approach, 1e-13);
  // The final layer's table re-sums to its share of the cut time.
  double chords = 0.0;
  for (const StepRow& row : r.steps_table) chords += row.chord_mm;
  EXPECT_NEAR(3.0 * chords / 250.0, 3.0 * 2.0 * 18.0 * std::sqrt(256.0 - 196.0) / 14.0 / 250.0,
              1e-13);
  // x_travel of the final layer (F8): (d + R)(1/cos alpha_e - 1).
  EXPECT_NEAR(r.x_travel_mm, 18.0 * (16.0 / 14.0 - 1.0), 1e-12);
}

TEST(LatheFlat, ShortestBlockIsTheMiddleChordOfTheShallowestLayer) {
  // F20: worked example 0.53336 mm; F21: 16 000.7 mm/min at 2 ms.
  LatheFlatResult r = computed(paper_flat());
  EXPECT_NEAR(r.shortest_block_mm, 0.53336, 0.5e-5);
  EXPECT_NEAR(r.max_feed_by_block_rate_mm_per_min, 16000.7, 0.05);
  EXPECT_NEAR(r.max_feed_by_block_rate_mm_per_min, 60000.0 * r.shortest_block_mm / 2.0, 1e-9);
  double table_min = 1e300;
  for (std::size_t i = 0; i + 1 < r.steps_table.size(); ++i) {
    table_min = std::min(table_min, r.steps_table[i].chord_mm);
  }
  EXPECT_NEAR(r.shortest_block_mm, table_min, 1e-12);
  // With layers, the shortest over all layers: (d_j + R) tan(alpha_e,j / N), minimised in the test.
  LatheFlatParams p = paper_flat();
  p.flat_depth_mm = 3.0;
  p.layer_depth_mm = 1.0;
  p.tool_radius_mm = 2.0;
  p.block_time_ms = 4.0;
  r = computed(p);
  double shortest = 1e300;
  for (const double t_j : {1.0, 2.0, 3.0}) {
    const double d_j = 16.0 - t_j;
    shortest = std::min(shortest, (d_j + 2.0) * std::tan(std::acos(d_j / 16.0) / 10.0));
  }
  EXPECT_NEAR(r.shortest_block_mm, shortest, 1e-12);
  EXPECT_NEAR(r.max_feed_by_block_rate_mm_per_min, 60000.0 * shortest / 4.0, 1e-8);
}

TEST(LatheFlatWarnings, FeedAboveTheBlockRateLimitWarnsOnlyAboveIt) {
  LatheFlatParams p = paper_flat();
  const double limit = computed(p).max_feed_by_block_rate_mm_per_min;
  p.feed_mm_per_min = limit;
  EXPECT_TRUE(warning_codes(p).empty());
  p.feed_mm_per_min = std::nextafter(limit, 2.0 * limit);
  EXPECT_EQ(warning_codes(p), std::vector<WarningCode>{WarningCode::feed_exceeds_block_rate});
  EXPECT_FALSE(computed(p).warnings.front().detail.empty());
}

TEST(LatheFlatWarnings, FlatnessOverToleranceOnlyWithBothStepsAndATolerance) {
  LatheFlatParams p = paper_flat();  // error(10) = 2.9531 um
  p.flatness_tolerance_mm = 0.0029;
  EXPECT_EQ(warning_codes(p), std::vector<WarningCode>{WarningCode::flatness_over_tolerance});
  p.flatness_tolerance_mm = computed(p).flatness_error_mm;  // equal: met
  EXPECT_TRUE(warning_codes(p).empty());
  p.flatness_tolerance_mm = 0.0029;
  p.steps.reset();  // the tolerance alone picks an N that meets it
  EXPECT_TRUE(warning_codes(p).empty());
  // Both warnings, in the order of section 5.
  p.steps = 10;
  p.feed_mm_per_min = 1e6;
  EXPECT_EQ(warning_codes(p), (std::vector<WarningCode>{WarningCode::feed_exceeds_block_rate,
                                                        WarningCode::flatness_over_tolerance}));
}

TEST(LatheFlatErrors, AFlatOutsideThePartIsRefusedAtEachGivenField) {
  // t >= R2, b >= D, d >= R2, s >= D; just inside is fine.
  LatheFlatParams base = paper_flat();
  base.flat_depth_mm.reset();
  base.flats = 2;
  struct Case {
    std::optional<double> LatheFlatParams::*field;
    double boundary;
  };
  for (const Case& c :
       {Case{&LatheFlatParams::flat_depth_mm, 16.0}, Case{&LatheFlatParams::flat_width_mm, 32.0},
        Case{&LatheFlatParams::axis_distance_mm, 16.0},
        Case{&LatheFlatParams::across_flats_mm, 32.0}}) {
    LatheFlatParams p = base;
    for (const double value : {c.boundary, c.boundary + 1.0}) {
      p.*c.field = value;
      EXPECT_EQ(refusal(p), ErrorCode::flat_outside_part) << c.boundary << " " << value;
    }
    p.*c.field = c.boundary * (1.0 - 1e-6);
    EXPECT_TRUE(compute_lathe_flat(p).ok()) << c.boundary;
  }
}

TEST(LatheFlatErrors, AToleranceNoThousandStepsMeetIsRefused) {
  LatheFlatParams p = paper_flat();
  p.part_diameter_mm = 1000.0;
  p.flat_depth_mm = 400.0;
  p.tool_radius_mm = 20.0;
  p.steps.reset();
  p.flatness_tolerance_mm = 1e-6;
  EXPECT_EQ(refusal(p), ErrorCode::tolerance_unmet);
  // With steps given as well, the tolerance is still searched and still refused.
  p.steps = 10;
  EXPECT_EQ(refusal(p), ErrorCode::tolerance_unmet);
}

TEST(LatheFlatErrors, MoreThan200000CuttingBlocksAreRefusedWithTheLimit) {
  // 2 N m L: N 1000, m 10, L 10 = 200 000 (allowed); L 11 is over.
  LatheFlatParams p = paper_flat();
  p.steps = 1000;
  p.flats = 10;
  p.layer_depth_mm = 0.1;
  const LatheFlatResult r = computed(p);
  EXPECT_EQ(r.layers, 10);
  EXPECT_EQ(r.cut_blocks, 200000);
  p.layer_depth_mm = 0.0999;
  const auto refused = compute_lathe_flat(p);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, ErrorCode::too_many_cut_blocks);
  ASSERT_TRUE(refused.error().limit.has_value());
  EXPECT_EQ(*refused.error().limit, 200000.0);
}

TEST(LatheFlatErrors, AVeryThinLayerIsRefusedByTheBlockCapBeforeTheLayersAreListed) {
  // t/a of 1e12 (or beyond an int) layers: too_many_cut_blocks, not a huge list or an overflow.
  LatheFlatParams p = paper_flat();
  for (const double a : {1e-12, 1e-300}) {
    p.layer_depth_mm = a;
    EXPECT_EQ(refusal(p), ErrorCode::too_many_cut_blocks) << a;
  }
}

}  // namespace
}  // namespace cutcalc::domain::lathe_flat
