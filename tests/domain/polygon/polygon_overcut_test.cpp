// Predicted overcut (spec polygon-holes.md section 7, P24-P26), the block-rate limit and the
// warnings (section 8, P27), the size and tolerance errors (section 10), and a randomized check
// that every output is finite and non-negative.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <set>
#include <string>

#include "domain/polygon/biarc_fit.h"
#include "domain/polygon/block_rate.h"
#include "domain/polygon/centre_path.h"
#include "domain/polygon/gcode_writer.h"
#include "domain/polygon/hole_prediction.h"
#include "domain/polygon/polygon_geometry.h"
#include "domain/polygon/rotor.h"
#include "polygon_test_support.h"

namespace {

namespace polygon_detail = cutcalc::domain::polygon::detail;
using cutcalc::domain::ErrorCode;
using cutcalc::domain::polygon::generate_polygon_hole;
using cutcalc::domain::polygon::predicted_overcut_mm;
using cutcalc::test::polygon::generate;
using cutcalc::test::polygon::hole;
using cutcalc::test::polygon::PolygonHoleParams;
using cutcalc::test::polygon::square_a16;
using cutcalc::test::polygon::Synchronization;

std::set<std::string> codes(const cutcalc::test::polygon::PolygonHoleResult& result) {
  std::set<std::string> set;
  for (const auto& warning : result.warnings) {
    set.emplace(cutcalc::domain::program::warning_name(warning.code));
  }
  return set;
}

// P26 is zero on the exact motion: the rotor at c(t) with phi = -t touches and never cuts.
TEST(PolygonOvercut, ZeroOnTheExactMotion) {
  for (int N = 3; N <= 12; ++N) {
    const polygon_detail::PolygonShape shape = polygon_detail::make_polygon_shape(N, 20.0);
    const polygon_detail::CentrePath path(shape);
    const polygon_detail::Rotor rotor(shape);
    for (int k = 0; k <= 300; ++k) {
      const double t = k * N * shape.delta / 300.0;
      EXPECT_NEAR(polygon_detail::penetration(shape, rotor, path.point(t), -t), 0.0, 1e-12) << N;
    }
  }
}

// Section 7 table, d = 20 and the square a = 16, 1 um fit, in um ("within a few percent": 2 %
// plus half a unit of the printed digits).
TEST(PolygonOvercut, SectionSevenTable) {
  struct Row {
    int N;
    double d;
    double feed_per_rev_um;
    double c_axis_um;
  };
  constexpr std::array<Row, 9> rows{{{3, 20, 439.4, 9.20},
                                     {4, 20, 51.80, 4.52},
                                     {5, 20, 11.57, 4.08},
                                     {6, 20, 4.11, 1.33},
                                     {7, 20, 1.83, 0.62},
                                     {8, 20, 0.96, 0.96},
                                     {9, 20, 0.50, 0.50},
                                     {12, 20, 0.10, 0.10},
                                     {4, 16, 41.44, 3.61}}};
  for (const Row& row : rows) {
    SCOPED_TRACE(testing::Message() << "N " << row.N << " d " << row.d);
    const double g95 =
        1000.0 *
        predicted_overcut_mm(generate(hole(row.N, row.d, 0.001, Synchronization::feed_per_rev)));
    const double c_axis =
        1000.0 * predicted_overcut_mm(generate(hole(row.N, row.d, 0.001, Synchronization::c_axis)));
    EXPECT_NEAR(g95, row.feed_per_rev_um, 0.02 * row.feed_per_rev_um + 0.006);
    EXPECT_NEAR(c_axis, row.c_axis_um, 0.02 * row.c_axis_um + 0.006);
  }
}

// The sampled-and-refined maximum equals a dense sampling (3000 per segment) for every N, both
// modes and several fits, to 1e-9 d.
TEST(PolygonOvercut, RefinedSamplingMatchesDenseSampling) {
  for (int N = 3; N <= 12; ++N) {
    for (const double tolerance : {0.002, 0.0005}) {
      SCOPED_TRACE(testing::Message() << "N " << N << " tol " << tolerance);
      const polygon_detail::PolygonShape shape = polygon_detail::make_polygon_shape(N, 1.0);
      const polygon_detail::CentrePath path(shape);
      const polygon_detail::Rotor rotor(shape);
      const auto fit = polygon_detail::fit_ellipse_arc(path, tolerance / 20.0);
      ASSERT_TRUE(fit.ok());
      const auto blocks = polygon_detail::loop_blocks(path, fit.value(), 1e-9);
      for (const auto sync : {Synchronization::feed_per_rev, Synchronization::c_axis}) {
        const auto segments = polygon_detail::motion_segments(shape, fit.value(), blocks, sync);
        const double refined = polygon_detail::predicted_overcut(shape, rotor, segments);
        const double dense = polygon_detail::predicted_overcut(shape, rotor, segments, 3000, false);
        EXPECT_GE(refined, dense - 1e-12);
        EXPECT_NEAR(refined, dense, 1e-9);
      }
    }
  }
}

// The congruent segments stand for the whole loop: the maximum over every block of the loop
// (c_axis: phi linear per block; feed_per_rev: phi linear in s over the loop) is the same.
TEST(PolygonOvercut, CongruentSegmentsCoverTheWholeLoop) {
  for (int N : {3, 4, 6, 9}) {
    SCOPED_TRACE(N);
    const polygon_detail::PolygonShape shape = polygon_detail::make_polygon_shape(N, 1.0);
    const polygon_detail::CentrePath path(shape);
    const polygon_detail::Rotor rotor(shape);
    const auto fit = polygon_detail::fit_ellipse_arc(path, 0.001 / 20.0);
    ASSERT_TRUE(fit.ok());
    const auto blocks = polygon_detail::loop_blocks(path, fit.value(), 1e-9);
    const double L_u = blocks.back().s_end;
    std::vector<polygon_detail::MotionSegment> whole_c_axis;
    std::vector<polygon_detail::MotionSegment> whole_g95;
    const double rate = -2.0 * std::numbers::pi / ((N - 1.0) * L_u);
    for (const auto& block : blocks) {
      whole_c_axis.push_back({block.arc, -block.t_start, -block.t_end});
      whole_g95.push_back({block.arc, rate * block.s_start, rate * block.s_end});
    }
    const auto c_axis =
        polygon_detail::motion_segments(shape, fit.value(), blocks, Synchronization::c_axis);
    const auto g95 =
        polygon_detail::motion_segments(shape, fit.value(), blocks, Synchronization::feed_per_rev);
    EXPECT_NEAR(polygon_detail::predicted_overcut(shape, rotor, c_axis),
                polygon_detail::predicted_overcut(shape, rotor, whole_c_axis, 400), 1e-10);
    EXPECT_NEAR(polygon_detail::predicted_overcut(shape, rotor, g95),
                polygon_detail::predicted_overcut(shape, rotor, whole_g95, 400), 1e-10);
  }
}

// m = 1: the C axis interpolates over the full circle, the same as G95.
TEST(PolygonOvercut, OneBlockLoopIsTheSameInBothModes) {
  for (int N : {8, 10, 12}) {
    const auto g95 = generate(hole(N, 20.0, 0.001, Synchronization::feed_per_rev));
    const auto c_axis = generate(hole(N, 20.0, 0.001, Synchronization::c_axis));
    ASSERT_EQ(g95.blocks_per_loop, 1);
    EXPECT_EQ(predicted_overcut_mm(g95), predicted_overcut_mm(c_axis));
  }
}

// Section 8: a = 16, 1 um, 2 ms: L_min 0.2294 mm, limit 6881 mm/min; at 30 rpm F_prog = 720.7.
// Hexagon d = 20 at 1000 rpm: 14 433 > 3 614 mm/min.
TEST(PolygonBlockRate, SectionEightExamples) {
  const polygon_detail::PolygonShape shape = polygon_detail::make_polygon_shape(4, 1.0);
  const polygon_detail::CentrePath path(shape);
  const auto fit = polygon_detail::fit_ellipse_arc(path, 0.001 / 16.0);
  ASSERT_TRUE(fit.ok());
  const auto blocks = polygon_detail::loop_blocks(path, fit.value(), 1e-9);
  const double L_min = 16.0 * polygon_detail::shortest_block_length(blocks);
  EXPECT_NEAR(L_min, 0.2294, 5e-5);
  EXPECT_NEAR(polygon_detail::max_feed_by_block_rate(L_min, 2.0), 6881.0, 0.5);

  const auto square = generate(square_a16());
  EXPECT_NEAR(square.max_feed_by_block_rate_mm_per_min, 6880.93938, 1e-5);
  EXPECT_NEAR(30.0 * square.feed_per_rev_mm, 720.7, 0.05);
  EXPECT_EQ(codes(square), std::set<std::string>{"phase_not_locked"});

  PolygonHoleParams hexagon = hole(6, 20.0, 0.001, Synchronization::c_axis);
  hexagon.spindle_speed_rpm = 1000.0;
  const auto fast = generate(hexagon);
  EXPECT_NEAR(1000.0 * fast.feed_per_rev_mm, 14433.0, 0.5);
  EXPECT_NEAR(fast.max_feed_by_block_rate_mm_per_min, 3614.0, 0.5);
  EXPECT_EQ(codes(fast), std::set<std::string>{"feed_exceeds_block_rate"});
  // A slower control (longer block time) lowers the limit proportionally.
  hexagon.spindle_speed_rpm = 30.0;
  hexagon.block_time_ms = 4.0;
  EXPECT_NEAR(generate(hexagon).max_feed_by_block_rate_mm_per_min, 0.5 * 3613.91515, 1e-4);
  EXPECT_TRUE(generate(hexagon).warnings.empty());
}

// Warnings: phase_not_locked always in feed_per_rev mode, never with c_axis.
TEST(PolygonBlockRate, PhaseWarningOnlyWithFeedPerRev) {
  for (int N = 3; N <= 12; ++N) {
    EXPECT_EQ(codes(generate(hole(N))), std::set<std::string>{"phase_not_locked"}) << N;
    EXPECT_TRUE(codes(generate(hole(N, 20.0, 0.001, Synchronization::c_axis))).empty()) << N;
  }
  PolygonHoleParams both = hole(6);
  both.spindle_speed_rpm = 1000.0;
  EXPECT_EQ(codes(generate(both)),
            (std::set<std::string>{"phase_not_locked", "feed_exceeds_block_rate"}));
}

// Section 10: more than 200 000 arc blocks, counted as (n loops_per_layer + (1 if 1)) blocks.
TEST(PolygonErrors, ProgramTooLarge) {
  EXPECT_EQ(polygon_detail::program_arc_blocks(2000.0, 100, 1), 200000.0);
  EXPECT_EQ(polygon_detail::program_arc_blocks(7999.0, 1, 25), 200000.0);
  PolygonHoleParams params = hole(6, 20.0, 0.005);  // 1 block per loop
  params.loops_per_layer = 100;
  params.depth_mm = 2.001;
  params.step_down_mm = 0.001;  // 2001 layers: 200 100 blocks
  const auto result = generate_polygon_hole(params);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().code, ErrorCode::program_too_large);
  params.depth_mm = 1e300;
  params.step_down_mm = 1e-300;  // depth / step overflows to infinity
  const auto overflow = generate_polygon_hole(params);
  ASSERT_FALSE(overflow.ok());
  EXPECT_EQ(overflow.error().code, ErrorCode::program_too_large);
}

TEST(PolygonErrors, LayerCountRoundsDownWithinOneBillionth) {
  EXPECT_EQ(polygon_detail::split_depth(0.3, 0.1).n, 3.0);  // 0.3 / 0.1 = 2.9999999999999996
  EXPECT_EQ(polygon_detail::split_depth(0.30000001, 0.1).n, 4.0);
  EXPECT_EQ(polygon_detail::split_depth(0.05, 0.1).n, 1.0);
  EXPECT_EQ(polygon_detail::split_depth(1e-12, 1000.0).n, 1.0);  // never zero layers
  EXPECT_NEAR(polygon_detail::split_depth(0.25, 0.1).dz, 0.25 / 3.0, 1e-17);
}

// Randomized valid inputs: every result is finite and non-negative, or one of the domain errors.
TEST(PolygonRobustness, RandomInputsGiveFiniteResults) {
  std::mt19937 random(2026);
  std::uniform_int_distribution<int> faces(3, 12);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int k = 0; k < 60; ++k) {
    PolygonHoleParams p;
    p.faces = faces(random);
    p.inscribed_diameter_mm = std::pow(10.0, 3.0 * unit(random));  // 1 .. 1000
    p.depth_mm = 0.01 + 2.0 * unit(random);
    p.step_down_mm = 0.05 + unit(random);
    p.spindle_speed_rpm = std::pow(10.0, 4.0 * unit(random));
    p.tolerance_mm = std::pow(10.0, -4.0 + 3.0 * unit(random));  // 0.0001 .. 0.1
    p.synchronization = k % 2 == 0 ? Synchronization::feed_per_rev : Synchronization::c_axis;
    if (k % 3 == 0) {
      p.loops_per_layer = 1 + static_cast<int>(unit(random) * 5.0);
    }
    p.safe_z_mm = 0.5 + 10.0 * unit(random);
    p.block_time_ms = 0.1 + 10.0 * unit(random);
    SCOPED_TRACE(testing::Message() << "N " << p.faces << " d " << p.inscribed_diameter_mm
                                    << " tol " << p.tolerance_mm);
    const auto result = generate_polygon_hole(p);
    if (!result.ok()) {
      EXPECT_TRUE(result.error().code == ErrorCode::tolerance_unreachable ||
                  result.error().code == ErrorCode::program_too_large);
      continue;
    }
    const auto& r = result.value();
    for (const double value :
         {r.loop_length_mm, r.feed_per_rev_mm, r.eccentricity_mm, r.max_path_deviation_mm,
          predicted_overcut_mm(r), r.uncut_corner_area_mm2, r.corner_gap_mm,
          r.max_feed_by_block_rate_mm_per_min}) {
      EXPECT_TRUE(std::isfinite(value));
      EXPECT_GE(value, 0.0);
    }
    EXPECT_GE(r.blocks_per_loop, 1);
    EXPECT_LE(r.max_path_deviation_mm, p.tolerance_mm);
    EXPECT_EQ(cutcalc::domain::polygon::program_text(r).find("nan"), std::string::npos);
    EXPECT_EQ(cutcalc::domain::polygon::program_text(r).find("inf"), std::string::npos);
  }
}

}  // namespace
