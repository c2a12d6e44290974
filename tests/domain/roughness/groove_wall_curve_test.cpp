// The Rz(S) curve of the groove side wall for plotting (spec roughness.md part R): the feed range,
// the sample count and spacing, monotone Rz (R7), each sample equal to a single-feed call, and
// the curve through (max_feed_mm, target) (R8).

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

#include "domain/common/result.h"
#include "domain/roughness/groove_wall.h"
#include "domain/roughness/groove_wall_curve.h"

namespace {

using cutcalc::domain::ErrorCode;
using cutcalc::domain::roughness::compute_groove_wall_curve;
using cutcalc::domain::roughness::compute_groove_wall_roughness;
using cutcalc::domain::roughness::CrestBranch;
using cutcalc::domain::roughness::GrooveWallCurve;
using cutcalc::domain::roughness::GrooveWallCurveParams;
using cutcalc::domain::roughness::GrooveWallParams;

GrooveWallCurve curve(const GrooveWallParams& groove, int points) {
  const auto result = compute_groove_wall_curve(GrooveWallCurveParams{groove, points});
  EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.error().detail);
  return result.ok() ? result.value() : GrooveWallCurve{};
}

// The spec's R.5 geometries with and without targets, all three branches, phi1 = 0.
std::vector<GrooveWallParams> requests() {
  return {
      {0.12, 0.3, 2.0, std::nullopt},  // R.5, branch B
      {0.12, 0.3, 2.0, 13.2},          // R.5 with the paper's 13.2 um: 1.25 S(T) wins
      {0.48, 0.3, 2.0, 2.0},           // target below Rz(S): 1.5 S wins
      {0.08, 0.3, 30.0, 5.0},          // branch A at the feed
      {10.0, 0.3, 2.0, 400.0},         // branch C at the feed
      {0.2, 0.4, 45.0, std::nullopt},  //
      {0.3, 0.3, 0.0, std::nullopt},   // phi1 = 0: Rz = 0 everywhere
      {1e-6, 1e-6, 89.9, 1e-6},        // the smallest accepted sizes
      {1e6, 1e6, 60.0, 1e9},           // the largest
  };
}

TEST(GrooveWallCurve, FeedsRunEvenlyFromTheFirstStepToTheMaximum) {
  for (const GrooveWallParams& groove : requests()) {
    const auto at_feed = compute_groove_wall_roughness(groove);
    ASSERT_TRUE(at_feed.ok());
    double feed_max = 1.5 * groove.feed_mm;
    if (at_feed.value().max_feed_mm) {
      feed_max = std::max(feed_max, 1.25 * *at_feed.value().max_feed_mm);
    }
    for (const int n : {2, 3, 50, 1000}) {
      SCOPED_TRACE(::testing::Message() << "S " << groove.feed_mm << " n " << n);
      const GrooveWallCurve c = curve(groove, n);
      ASSERT_EQ(c.points.size(), static_cast<std::size_t>(n));
      EXPECT_EQ(c.feed_max_mm, feed_max);
      EXPECT_EQ(c.points.back().feed_mm, feed_max);
      EXPECT_NEAR(c.points.front().feed_mm, feed_max / n, 1e-15 * feed_max);
      for (std::size_t k = 1; k < c.points.size(); ++k) {
        EXPECT_NEAR(c.points[k].feed_mm - c.points[k - 1].feed_mm, feed_max / n, 1e-12 * feed_max);
      }
    }
  }
}

TEST(GrooveWallCurve, TheRangeShowsTheFeedAndTheMaximumFeed) {
  // R.5: S(13.2 um) = 0.471245 mm > 1.5 x 0.12, so the curve runs to 1.25 x 0.471245.
  const GrooveWallCurve with_target = curve({0.12, 0.3, 2.0, 13.2}, 100);
  EXPECT_NEAR(with_target.feed_max_mm, 1.25 * 0.4712450622448343, 1e-12);
  // Without a target, or with one the feed already exceeds, 1.5 S.
  EXPECT_EQ(curve({0.12, 0.3, 2.0, std::nullopt}, 100).feed_max_mm, 1.5 * 0.12);
  EXPECT_EQ(curve({0.48, 0.3, 2.0, 2.0}, 100).feed_max_mm, 1.5 * 0.48);
}

TEST(GrooveWallCurve, EachSampleEqualsASingleFeedCall) {
  for (const GrooveWallParams& groove : requests()) {
    const GrooveWallCurve c = curve(groove, 200);
    for (const auto& point : c.points) {
      const auto single = compute_groove_wall_roughness(
          {point.feed_mm, groove.nose_radius_mm, groove.minor_edge_angle_deg, std::nullopt});
      ASSERT_TRUE(single.ok());
      EXPECT_EQ(point.rz_um, single.value().rz_um) << point.feed_mm;
      EXPECT_EQ(point.branch, single.value().branch) << point.feed_mm;
    }
  }
}

TEST(GrooveWallCurve, RzRisesWithTheFeedThroughTheBranchesInOrder) {
  for (const GrooveWallParams& groove : requests()) {
    const GrooveWallCurve c = curve(groove, 1000);
    for (std::size_t k = 1; k < c.points.size(); ++k) {
      if (groove.minor_edge_angle_deg > 0.0) {
        EXPECT_GT(c.points[k].rz_um, c.points[k - 1].rz_um) << c.points[k].feed_mm;  // R7
      } else {
        EXPECT_EQ(c.points[k].rz_um, 0.0);  // R4 with phi1 = 0
      }
      EXPECT_GE(static_cast<int>(c.points[k].branch), static_cast<int>(c.points[k - 1].branch));
    }
  }
  // R.5, phi1 = 2 deg, 0.015 to 15 mm: all three branches appear (S_AB = 0.02094 mm,
  // S_BC = 8.8961 mm).
  const GrooveWallCurve c = curve({10.0, 0.3, 2.0, std::nullopt}, 1000);
  EXPECT_EQ(c.points.front().branch, CrestBranch::nose_arc);
  EXPECT_EQ(c.points[1].branch, CrestBranch::nose_arc_and_minor_edge);
  EXPECT_EQ(c.points.back().branch, CrestBranch::minor_edge_and_main_edge);
}

TEST(GrooveWallCurve, PassesThroughTheMaximumFeedAtTheTarget) {
  for (const GrooveWallParams& groove : requests()) {
    if (!groove.target_rz_um) {
      continue;
    }
    const auto at_feed = compute_groove_wall_roughness(groove);
    ASSERT_TRUE(at_feed.ok());
    const double max_feed = *at_feed.value().max_feed_mm;
    const double target = *groove.target_rz_um;
    const GrooveWallCurve c = curve(groove, 400);
    // The samples around S(T) bracket T, and the chord between them meets T within the chord's
    // own bend (the curve is C1, R7).
    std::size_t k = 0;
    while (k + 1 < c.points.size() && c.points[k + 1].feed_mm < max_feed) {
      ++k;
    }
    ASSERT_LT(k + 1, c.points.size()) << "S(T) beyond the curve";
    const auto& below = c.points[k];
    const auto& above = c.points[k + 1];
    SCOPED_TRACE(::testing::Message() << "S " << groove.feed_mm << " T " << target);
    EXPECT_LE(below.feed_mm, max_feed);
    EXPECT_GE(above.feed_mm, max_feed);
    EXPECT_LE(below.rz_um, target * (1.0 + 1e-12));
    EXPECT_GE(above.rz_um, target * (1.0 - 1e-12));
    const double f = (max_feed - below.feed_mm) / (above.feed_mm - below.feed_mm);
    const double chord = below.rz_um + f * (above.rz_um - below.rz_um);
    EXPECT_NEAR(chord, target, 0.01 * (above.rz_um - below.rz_um) + 1e-12 * target);
  }
}

TEST(GrooveWallCurve, ErrorsOfTheRequestAreTheCurvesErrors) {
  // R.4: a target with phi1 = 0 has no largest feed.
  const auto flat = compute_groove_wall_curve({{0.1, 0.3, 0.0, 5.0}, 10});
  ASSERT_FALSE(flat.ok());
  EXPECT_EQ(flat.error().code, ErrorCode::target_needs_minor_edge_angle);
  // S(T) is finite (about 1.6e308 mm) but 1.25 S(T) is not: the range cannot be drawn.
  const GrooveWallParams vanishing{0.1, 0.3, 3.5e-301, 1e9};
  const auto at_feed = compute_groove_wall_roughness(vanishing);
  ASSERT_TRUE(at_feed.ok());
  ASSERT_TRUE(std::isfinite(*at_feed.value().max_feed_mm));
  const auto overflow = compute_groove_wall_curve({vanishing, 10});
  ASSERT_FALSE(overflow.ok());
  EXPECT_EQ(overflow.error().code, ErrorCode::target_needs_minor_edge_angle);
}

}  // namespace
