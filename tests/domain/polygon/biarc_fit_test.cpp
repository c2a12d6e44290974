// Arc fitting, spec polygon-holes.md section 6 (P18-P21): the equal-tangent biarc, the blocks
// per loop table, the deviation bound checked independently, merging, m = 1, and the junction
// parameters of the block ends.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "domain/polygon/biarc_fit.h"
#include "domain/polygon/centre_path.h"
#include "domain/polygon/polygon_geometry.h"
#include "polygon_test_support.h"

namespace {

namespace polygon_detail = cutcalc::domain::polygon::detail;
using cutcalc::domain::ErrorCode;
using cutcalc::test::polygon::generate;
using cutcalc::test::polygon::hole;
using cutcalc::test::polygon::kPi;

Eigen::Vector2d end_tangent(const polygon_detail::FittedArc& arc) {
  const double sense = arc.sweep > 0.0 ? 1.0 : -1.0;
  return sense * polygon_detail::unit(arc.start_angle + arc.sweep + 0.5 * kPi);
}

Eigen::Vector2d start_tangent(const polygon_detail::FittedArc& arc) {
  const double sense = arc.sweep > 0.0 ? 1.0 : -1.0;
  return sense * polygon_detail::unit(arc.start_angle + 0.5 * kPi);
}

// P19: the biarc joins both end points with their tangents, tangent-continuously, with equal
// tangent lengths.
TEST(BiarcFit, EqualTangentBiarcJoinsPointsAndTangents) {
  const Eigen::Vector2d P0(0.0, 0.0);
  const Eigen::Vector2d P1(3.0, 1.0);
  for (const double turn : {0.0, 0.2, 0.7, 1.3}) {
    SCOPED_TRACE(turn);
    const Eigen::Vector2d T0 = polygon_detail::unit(0.1);
    const Eigen::Vector2d T1 = polygon_detail::unit(0.1 + turn);
    const auto biarc = polygon_detail::fit_biarc(P0, T0, P1, T1);
    if (turn == 0.0) {
      // Equal tangents not along the chord: an S-curve of two opposite arcs.
      ASSERT_TRUE(biarc.has_value());
      EXPECT_LT(biarc->first.sweep * biarc->second.sweep, 0.0);
    }
    ASSERT_TRUE(biarc.has_value());
    EXPECT_NEAR((biarc->first.start - P0).norm(), 0.0, 1e-15);
    EXPECT_NEAR((biarc->second.end - P1).norm(), 0.0, 1e-15);
    EXPECT_NEAR((biarc->first.end - biarc->junction).norm(), 0.0, 1e-15);
    EXPECT_NEAR((start_tangent(biarc->first) - T0).norm(), 0.0, 1e-12);
    EXPECT_NEAR((end_tangent(biarc->first) - start_tangent(biarc->second)).norm(), 0.0, 1e-12);
    EXPECT_NEAR((end_tangent(biarc->second) - T1).norm(), 0.0, 1e-12);
    // The arcs pass through their end points at their radius.
    EXPECT_NEAR((biarc->second.end - biarc->second.centre).norm(), biarc->second.radius, 1e-12);
  }
}

// Section 6 table, d = 20 (a = 16 as N = 4): blocks per loop at 5, 2, 1 and 0.5 um.
TEST(BiarcFit, BlocksPerLoopTableForDiameterTwenty) {
  const std::array<double, 4> tolerances{0.005, 0.002, 0.001, 0.0005};
  const std::array<std::array<int, 10>, 4> table{{
      {25, 9, 11, 1, 1, 1, 1, 1, 1, 1},
      {31, 17, 11, 13, 1, 1, 1, 1, 1, 1},
      {43, 25, 11, 13, 15, 1, 1, 1, 1, 1},
      {55, 33, 21, 13, 15, 17, 1, 1, 1, 1},
  }};
  for (std::size_t row = 0; row < tolerances.size(); ++row) {
    for (int N = 3; N <= 12; ++N) {
      SCOPED_TRACE(testing::Message() << "tol " << tolerances[row] << " N " << N);
      const auto result = generate(hole(N, 20.0, tolerances[row]));
      const int want = table[row][static_cast<std::size_t>(N - 3)];
      EXPECT_LE(result.blocks_per_loop, want);
      EXPECT_EQ(result.blocks_per_loop, want);
      EXPECT_LE(result.max_path_deviation_mm, tolerances[row]);
    }
  }
  EXPECT_EQ(generate(hole(4, 16.0, 0.001)).blocks_per_loop, 25);
  EXPECT_EQ(generate(hole(4, 16.0, 0.005)).blocks_per_loop, 9);
}

// P21: blocks_per_loop = 2 N (m - 1) + 1 for m >= 2 (joins at mid-phases and phase changes
// merge), the arc through the start split into the first and the last block.
TEST(BiarcFit, MergingLeavesTwoNTimesMMinusOnePlusOneBlocks) {
  for (int N = 3; N <= 12; ++N) {
    for (const double tolerance : {0.002, 0.0005, 0.0001}) {
      SCOPED_TRACE(testing::Message() << "N " << N << " tol " << tolerance);
      const polygon_detail::PolygonShape shape = polygon_detail::make_polygon_shape(N, 1.0);
      const polygon_detail::CentrePath path(shape);
      const auto fit = polygon_detail::fit_ellipse_arc(path, tolerance / 20.0);
      ASSERT_TRUE(fit.ok());
      const auto blocks = polygon_detail::loop_blocks(path, fit.value(), 1e-9);
      const int m = fit.value().m;
      if (m == 1) {
        ASSERT_EQ(blocks.size(), 1U);
        continue;
      }
      EXPECT_EQ(static_cast<int>(blocks.size()), 2 * N * (m - 1) + 1);
      EXPECT_NEAR((blocks.front().arc.centre - blocks.back().arc.centre).norm(), 0.0, 1e-9);
      EXPECT_NEAR(blocks.front().arc.radius, blocks.back().arc.radius, 1e-9);
      // Consecutive blocks are different circles and share their end points.
      for (std::size_t b = 1; b < blocks.size(); ++b) {
        EXPECT_GT((blocks[b].arc.centre - blocks[b - 1].arc.centre).norm() +
                      std::abs(blocks[b].arc.radius - blocks[b - 1].arc.radius),
                  1e-9);
        EXPECT_NEAR((blocks[b].arc.start - blocks[b - 1].arc.end).norm(), 0.0, 1e-14);
        EXPECT_EQ(blocks[b].t_start, blocks[b - 1].t_end);
        EXPECT_GT(blocks[b].arc.sweep, 0.0);
      }
    }
  }
}

// P21, m = 1: one full circle of radius e about the hole centre, deviation r_max - e.
TEST(BiarcFit, OneBiarcIsTheCircleOfRadiusE) {
  const polygon_detail::PolygonShape shape = polygon_detail::make_polygon_shape(8, 1.0);
  const polygon_detail::CentrePath path(shape);
  const auto fit = polygon_detail::fit_ellipse_arc(path, 0.001 / 20.0);
  ASSERT_TRUE(fit.ok());
  ASSERT_EQ(fit.value().m, 1);
  const auto blocks = polygon_detail::loop_blocks(path, fit.value(), 1e-9);
  ASSERT_EQ(blocks.size(), 1U);
  EXPECT_NEAR(blocks[0].arc.centre.norm(), 0.0, 1e-14);
  EXPECT_NEAR(blocks[0].arc.radius, shape.e, 1e-14);
  EXPECT_NEAR(blocks[0].arc.sweep, 2.0 * kPi, 1e-13);
  EXPECT_EQ(blocks[0].arc.end, blocks[0].arc.start);
  EXPECT_NEAR(blocks[0].t_end, 2.0 * kPi / 7.0, 1e-14);
  // The P20 samples miss the exact mid-phase by half a sample step: within 1e-4 relative.
  EXPECT_NEAR(fit.value().deviation, shape.r_max - shape.e, 1e-4 * (shape.r_max - shape.e));
  EXPECT_LE(fit.value().deviation, shape.r_max - shape.e);
}

// P20 written out literally (exact sines, atan2 spans, every polyline segment) for all m biarcs:
// the fit's deviation (sampled by rotation, nearest segment by descent, mirror symmetry) agrees.
TEST(BiarcFit, DeviationMatchesALiteralP20) {
  auto arc_distance = [](const polygon_detail::FittedArc& arc, const Eigen::Vector2d& P) {
    const double a = std::atan2(P.y() - arc.centre.y(), P.x() - arc.centre.x());
    double from_start = std::remainder(a - arc.start_angle, 2.0 * kPi);
    if (from_start < 0.0) {
      from_start += 2.0 * kPi;
    }
    if (from_start <= arc.sweep) {
      return std::abs((P - arc.centre).norm() - arc.radius);
    }
    return std::min((P - arc.start).norm(), (P - arc.end).norm());
  };
  for (const auto& [N, tolerance] : {std::pair{3, 0.002}, std::pair{4, 0.0003}, std::pair{5, 0.001},
                                     std::pair{7, 0.0005}, std::pair{12, 0.002}}) {
    SCOPED_TRACE(testing::Message() << "N " << N << " tol " << tolerance);
    const polygon_detail::PolygonShape shape = polygon_detail::make_polygon_shape(N, 1.0);
    const polygon_detail::CentrePath path(shape);
    const auto fit = polygon_detail::fit_ellipse_arc(path, tolerance / 20.0);
    ASSERT_TRUE(fit.ok());
    const int m = fit.value().m;
    double deviation = 0.0;
    for (int i = 0; i < m; ++i) {
      const polygon_detail::Biarc& biarc = fit.value().biarcs[static_cast<std::size_t>(i)];
      const double t0 = i * shape.delta / m;
      const double t1 = (i + 1) * shape.delta / m;
      std::vector<Eigen::Vector2d> samples;
      for (int k = 0; k < 300; ++k) {
        samples.push_back(path.point_in_phase(0, t0 + k * (t1 - t0) / 299));
        deviation = std::max(deviation, std::min(arc_distance(biarc.first, samples.back()),
                                                 arc_distance(biarc.second, samples.back())));
      }
      for (const polygon_detail::FittedArc* arc : {&biarc.first, &biarc.second}) {
        for (int k = 0; k < 150; ++k) {
          const Eigen::Vector2d P =
              arc->centre +
              arc->radius * polygon_detail::unit(arc->start_angle + k * arc->sweep / 149);
          double nearest = std::numeric_limits<double>::infinity();
          for (std::size_t j = 0; j + 1 < samples.size(); ++j) {
            const Eigen::Vector2d ab = samples[j + 1] - samples[j];
            const double f = std::clamp((P - samples[j]).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
            nearest = std::min(nearest, (P - samples[j] - f * ab).norm());
          }
          deviation = std::max(deviation, nearest);
        }
      }
    }
    EXPECT_NEAR(fit.value().deviation, deviation, 1e-14);
  }
}

// P21: the smallest m. m - 1 biarcs do not hold the tolerance.
TEST(BiarcFit, ChoosesTheSmallestM) {
  for (int N = 3; N <= 12; ++N) {
    SCOPED_TRACE(N);
    const polygon_detail::PolygonShape shape = polygon_detail::make_polygon_shape(N, 1.0);
    const polygon_detail::CentrePath path(shape);
    const double tolerance = 0.0005 / 20.0;
    const auto fit = polygon_detail::fit_ellipse_arc(path, tolerance);
    ASSERT_TRUE(fit.ok());
    EXPECT_LE(fit.value().deviation, tolerance);
    const int m = fit.value().m;
    if (m > 1) {
      const auto smaller = polygon_detail::fit_ellipse_arc(path, tolerance, m - 1);
      ASSERT_FALSE(smaller.ok());
      EXPECT_EQ(smaller.error().code, ErrorCode::tolerance_unreachable);
    }
  }
}

// P20 checked independently: dense samples of the exact loop to the nearest block of the fitted
// loop (brute force over all blocks), and dense samples of every block to the exact path
// (nearest point by a fine search), stay within the tolerance (plus the P20 sampling slack).
TEST(BiarcFit, FittedLoopStaysWithinTheTolerance) {
  struct Case {
    int N;
    double d;
    double tolerance;
  };
  for (const Case& c : {Case{3, 20.0, 0.0005}, Case{4, 16.0, 0.001}, Case{5, 20.0, 0.001},
                        Case{6, 20.0, 0.002}, Case{8, 20.0, 0.0005}, Case{11, 24.0, 0.0001},
                        Case{4, 5.0, 0.0001}, Case{3, 300.0, 0.01}}) {
    SCOPED_TRACE(testing::Message() << "N " << c.N << " d " << c.d << " tol " << c.tolerance);
    const polygon_detail::PolygonShape shape = polygon_detail::make_polygon_shape(c.N, c.d);
    const polygon_detail::CentrePath path(shape);
    const auto fit = polygon_detail::fit_ellipse_arc(path, c.tolerance);
    ASSERT_TRUE(fit.ok());
    const auto blocks = polygon_detail::loop_blocks(path, fit.value(), 1e-9 * c.d);
    double path_to_arcs = 0.0;
    constexpr int samples = 1500;
    for (int k = 0; k <= samples; ++k) {
      const Eigen::Vector2d P = path.point(k * c.N * shape.delta / samples);
      double nearest = std::numeric_limits<double>::infinity();
      for (const auto& block : blocks) {
        nearest = std::min(nearest, block.arc.distance_to(P));
      }
      path_to_arcs = std::max(path_to_arcs, nearest);
    }
    // Arc samples to the exact path: the nearest exact point by a scan of t around the block's
    // own parameter range, refined by golden section.
    double arcs_to_path = 0.0;
    for (const auto& block : blocks) {
      for (int k = 0; k <= 16; ++k) {
        const Eigen::Vector2d P = block.arc.point_at(k / 16.0);
        auto distance = [&](double t) { return (path.point(t) - P).norm(); };
        const double lo = std::max(0.0, block.t_start - 0.05 * shape.delta);
        const double step = (block.t_end + 0.05 * shape.delta - lo) / 100.0;
        double best_t = lo;
        for (int s = 1; s <= 100; ++s) {
          if (distance(lo + s * step) < distance(best_t)) {
            best_t = lo + s * step;
          }
        }
        double a = std::max(0.0, best_t - step);
        double b = best_t + step;
        for (int iteration = 0; iteration < 60; ++iteration) {
          const double m1 = a + (b - a) / 3.0;
          const double m2 = b - (b - a) / 3.0;
          if (distance(m1) < distance(m2)) {
            b = m2;
          } else {
            a = m1;
          }
        }
        arcs_to_path = std::max(arcs_to_path, distance(0.5 * (a + b)));
      }
    }
    EXPECT_LE(path_to_arcs, c.tolerance * 1.01);
    EXPECT_LE(path_to_arcs, fit.value().deviation * 1.01 + 1e-12);
    EXPECT_LE(arcs_to_path, c.tolerance * 1.01);
  }
}

// P21: a block that ends at a biarc junction ends at the parameter of the exact-path point
// nearest to the junction: <c(t_end) - J, c'(t_end)> = 0.
TEST(BiarcFit, JunctionEndsAtTheNearestExactPoint) {
  for (int N : {3, 4, 5, 7}) {
    SCOPED_TRACE(N);
    const polygon_detail::PolygonShape shape = polygon_detail::make_polygon_shape(N, 1.0);
    const polygon_detail::CentrePath path(shape);
    const auto fit = polygon_detail::fit_ellipse_arc(path, 0.0005 / 20.0);
    ASSERT_TRUE(fit.ok());
    const int m = fit.value().m;
    for (int i = 0; i < m; ++i) {
      const double t = fit.value().junction_theta[static_cast<std::size_t>(i)];
      EXPECT_GT(t, i * shape.delta / m);
      EXPECT_LT(t, (i + 1) * shape.delta / m);
      const Eigen::Vector2d J = fit.value().biarcs[static_cast<std::size_t>(i)].junction;
      const Eigen::Vector2d tangent = path.velocity_in_phase(0, t).normalized();
      // Golden section on the squared distance resolves t to about sqrt(eps): 1e-9 d here.
      EXPECT_NEAR((path.point_in_phase(0, t) - J).dot(tangent), 0.0, 1e-9);
    }
    // Knot ends carry t_i = i delta / m; the loop ends at N delta.
    const auto blocks = polygon_detail::loop_blocks(path, fit.value(), 1e-9);
    EXPECT_NEAR(blocks.back().t_end, 2.0 * kPi / (N - 1.0), 1e-14);
  }
}

TEST(BiarcFit, UnreachableToleranceIsAnError) {
  auto params = hole(3, 1e7, 0.0001);
  const auto result = cutcalc::domain::polygon::generate_polygon_hole(params);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().code, ErrorCode::tolerance_unreachable);
  params.inscribed_diameter_mm = 1e300;
  const auto huge = cutcalc::domain::polygon::generate_polygon_hole(params);
  ASSERT_FALSE(huge.ok());
  EXPECT_EQ(huge.error().code, ErrorCode::tolerance_unreachable);
}

}  // namespace
