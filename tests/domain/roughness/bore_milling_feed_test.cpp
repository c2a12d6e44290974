// Bore milling, spec roughness.md addition B.9: the largest accepted feed S_lim (B9-B10), the
// largest feed for a target cusp (B12), the cusp curve (B13), and the numerical check B11 that
// the bisections rely on.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <optional>
#include <random>

#include "domain/common/milling_sense.h"
#include "domain/common/result.h"
#include "domain/roughness/bore_milling.h"
#include "domain/roughness/bore_milling_curve.h"
#include "domain/roughness/bore_milling_feed.h"
#include "domain/roughness/roughness_test_support.h"

namespace {

using cutcalc::domain::ErrorCode;
using cutcalc::domain::MillingSense;
using cutcalc::domain::roughness::bore_milling_feed_accepted;
using cutcalc::domain::roughness::bore_milling_feed_limit_mm;
using cutcalc::domain::roughness::bore_milling_max_feed_mm;
using cutcalc::domain::roughness::BoreMillingParams;
using cutcalc::domain::roughness::compute_bore_milling_curve;
using cutcalc::domain::roughness::compute_bore_milling_cusp;

using cutcalc::test::roughness::kDown;
using cutcalc::test::roughness::kUp;

using cutcalc::test::roughness::bore_printed;

BoreMillingParams setup(double R, double r, int n, MillingSense milling, double S = 0.1) {
  return BoreMillingParams{R, r, n, S, milling};
}

BoreMillingParams at_feed(BoreMillingParams params, double S) {
  params.feed_per_rev_mm = S;
  return params;
}

// Relative width of the band above S_lim in which the rounding of eps may still accept a feed.
constexpr double kRoundingNoise = 1e-13;

// B9: S_top, the end of the feeds B10 searches.
double feed_top_mm(const BoreMillingParams& p) {
  const double Rc = p.bore_radius_mm - p.cutter_radius_mm;
  const double n = p.teeth;
  return p.milling == kUp ? 2.0 * std::numbers::pi * Rc * n / (n + 2.0)
                          : 2.0 * std::numbers::pi * std::min(Rc, p.cutter_radius_mm);
}

double cusp_um(const BoreMillingParams& params, double S) {
  const auto result = compute_bore_milling_cusp(at_feed(params, S));
  EXPECT_TRUE(result.ok()) << "S " << S;
  return result.ok() ? result.value().cusp_height_um : -1.0;
}

double max_feed(const BoreMillingParams& params, double target_um) {
  const auto result = bore_milling_max_feed_mm(params, target_um);
  EXPECT_TRUE(result.ok()) << "T " << target_um;
  return result.ok() ? result.value() : -1.0;
}

// B10: S_lim is accepted and a feed above it is not. Within a few doubles of a limit of B.4 steps
// 2-3 (eps = 1, alpha = 180 deg) the rounding of eps can accept and refuse alternately, so "above"
// is beyond that noise: 1e-13 relative. The spec's B.9 examples.
TEST(BoreMillingFeedLimit, IsTheLastAcceptedFeed) {
  for (const BoreMillingParams& params :
       {setup(81.0, 32.4, 4, kUp), setup(81.0, 32.4, 4, kDown), setup(20.0, 8.0, 1, kUp),
        setup(20.0, 8.0, 1, kDown), setup(20.0, 8.0, 2, kUp), setup(5.0, 4.5, 12, kDown),
        setup(100.0, 5.0, 3, kUp)}) {
    const double S_lim = bore_milling_feed_limit_mm(params);
    SCOPED_TRACE(testing::Message()
                 << "R " << params.bore_radius_mm << " n " << params.teeth << " S_lim " << S_lim);
    EXPECT_GT(S_lim, 0.0);
    EXPECT_TRUE(bore_milling_feed_accepted(at_feed(params, S_lim)));
    EXPECT_LT(S_lim, feed_top_mm(params));
    EXPECT_FALSE(bore_milling_feed_accepted(at_feed(params, S_lim * (1.0 + kRoundingNoise))));
  }
  // B.9 example: Table 1 setting, up, S_lim 203.58; R 20, r 8, n 1, up, S_lim 20.54.
  EXPECT_NEAR(bore_milling_feed_limit_mm(setup(81.0, 32.4, 4, kUp)), 203.58, bore_printed(0.01));
  EXPECT_NEAR(bore_milling_feed_limit_mm(setup(20.0, 8.0, 1, kUp)), 20.54, bore_printed(0.01));
}

// B9: for n = 2 up-milling the pitch angle limit alpha = 180 deg (S_top = 2 pi Rc n / (n + 2))
// comes first: S_lim sits just below it.
TEST(BoreMillingFeedLimit, StopsAtThePitchAngleLimit) {
  const double S_top = 2.0 * std::numbers::pi * 12.0 * 0.5;
  const double S_lim = bore_milling_feed_limit_mm(setup(20.0, 8.0, 2, kUp));
  EXPECT_LE(S_lim, S_top);
  EXPECT_NEAR(S_lim, S_top, 1e-13 * S_top);
}

// The limit does not depend on the request's feed.
TEST(BoreMillingFeedLimit, IgnoresTheFeed) {
  BoreMillingParams params = setup(81.0, 32.4, 4, kDown, 0.2);
  const double S_lim = bore_milling_feed_limit_mm(params);
  params.feed_per_rev_mm = 500.0;
  EXPECT_EQ(bore_milling_feed_limit_mm(params), S_lim);
}

// B12, the spec's B.9 examples, and Delta(S(T)) = T.
TEST(BoreMillingMaxFeed, SpecExamples) {
  const BoreMillingParams table1 = setup(81.0, 32.4, 4, kUp, 0.2);
  const double S1 = max_feed(table1, 0.05);
  EXPECT_NEAR(S1, 0.353339, bore_printed(1e-6));
  EXPECT_NEAR(cusp_um(table1, S1), 0.05, 1e-12 * 0.05);
  const BoreMillingParams small = setup(20.0, 8.0, 1, kUp, 2.0);
  const double S2 = max_feed(small, 1.0);
  EXPECT_NEAR(S2, 0.196725, bore_printed(1e-6));
  EXPECT_NEAR(cusp_um(small, S2), 1.0, 1e-12);
}

// B12: the answer is the last feed whose cusp stays within the target.
TEST(BoreMillingMaxFeed, IsTheLastFeedWithinTheTarget) {
  for (const MillingSense milling : {kUp, kDown}) {
    const BoreMillingParams params = setup(20.0, 8.0, 3, milling, 1.0);
    for (const double T : {1e-6, 0.01, 1.0, 50.0, 400.0}) {
      const double S = max_feed(params, T);
      SCOPED_TRACE(testing::Message() << "T " << T << " S " << S);
      EXPECT_LE(cusp_um(params, S), T);
      EXPECT_GT(cusp_um(params, std::nextafter(S, std::numeric_limits<double>::infinity())), T);
    }
  }
}

// B12: a target equal to the cusp of a feed gives that feed back; the request's own feed plays no
// part.
TEST(BoreMillingMaxFeed, TargetAtAFeedsCuspGivesThatFeed) {
  const BoreMillingParams params = setup(20.0, 8.0, 2, kUp, 1.0);
  const double T = cusp_um(params, 1.0);
  EXPECT_NEAR(max_feed(params, T), 1.0, 1e-12);
  EXPECT_EQ(max_feed(at_feed(params, 7.0), T), max_feed(params, T));
}

// B12: a target above Delta(S_lim) is refused, stating Delta(S_lim).
TEST(BoreMillingMaxFeed, TargetBeyondTheModelIsRefused) {
  const BoreMillingParams params = setup(20.0, 8.0, 1, kUp, 2.0);
  const double cusp_at_limit = cusp_um(params, bore_milling_feed_limit_mm(params));
  const auto refused = bore_milling_max_feed_mm(params, 1.0001 * cusp_at_limit);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, ErrorCode::target_cusp_unreachable);
  ASSERT_TRUE(refused.error().limit.has_value());
  EXPECT_EQ(*refused.error().limit, cusp_at_limit);
  // Delta(S_lim) itself is reachable: at S_lim.
  EXPECT_EQ(max_feed(params, cusp_at_limit), bore_milling_feed_limit_mm(params));
}

// B13: S_max = 1.5 S without a target, max(1.5 S, 1.25 S(T)) with one, never beyond S_lim; the
// samples are S_max j / k and each is the answer at its feed.
TEST(BoreMillingCurve, RangeAndSamples) {
  BoreMillingParams params = setup(20.0, 8.0, 1, kDown, 2.0);
  auto curve = compute_bore_milling_curve({params, std::nullopt, 5});
  ASSERT_TRUE(curve.ok());
  EXPECT_EQ(curve.value().feed_max_mm, 3.0);
  ASSERT_EQ(curve.value().points.size(), 5u);
  double previous = 0.0;
  for (std::size_t j = 0; j < 5; ++j) {
    const auto& point = curve.value().points[j];
    EXPECT_DOUBLE_EQ(point.feed_per_rev_mm, 3.0 * static_cast<double>(j + 1) / 5.0);
    EXPECT_EQ(point.cusp_height_um, cusp_um(params, point.feed_per_rev_mm));
    EXPECT_GT(point.cusp_height_um, previous);  // B11: Delta rises with the feed
    previous = point.cusp_height_um;
  }
  // With a target whose feed is far right of 1.5 S: 1.25 S(T).
  const double S_T = max_feed(params, 500.0);
  curve = compute_bore_milling_curve({params, S_T, 4});
  ASSERT_TRUE(curve.ok());
  EXPECT_EQ(curve.value().feed_max_mm, 1.25 * S_T);
  EXPECT_EQ(curve.value().points.back().feed_per_rev_mm, curve.value().feed_max_mm);
  // A feed near S_lim: capped at S_lim, the last sample accepted.
  params = setup(20.0, 8.0, 1, kUp, 15.0);
  curve = compute_bore_milling_curve({params, std::nullopt, 3});
  ASSERT_TRUE(curve.ok());
  EXPECT_EQ(curve.value().feed_max_mm, bore_milling_feed_limit_mm(params));
  EXPECT_EQ(curve.value().points.back().feed_per_rev_mm, bore_milling_feed_limit_mm(params));
}

// B13: the request's own errors are the curve's.
TEST(BoreMillingCurve, RequestErrorsStay) {
  // bmn-curve-capped's request: its feed 25 lies above S_lim = 20.54 (B.4 step 4 refuses it).
  const auto too_fast =
      compute_bore_milling_curve({setup(20.0, 8.0, 1, kUp, 25.0), std::nullopt, 3});
  ASSERT_FALSE(too_fast.ok());
  EXPECT_EQ(too_fast.error().code, ErrorCode::bore_feed_too_large);
  const auto not_smaller = compute_bore_milling_curve({setup(8.0, 8.0, 1, kUp, 2.0), 3.0, 3});
  ASSERT_FALSE(not_smaller.ok());
  EXPECT_EQ(not_smaller.error().code, ErrorCode::cutter_not_smaller_than_bore);
}

// B11, the numerical check the bisections rely on (a smaller sample than the spec's 300 setups):
// below S_top the accepted feeds are exactly (0, S_lim], and Delta rises on them.
TEST(BoreMillingFeedLimit, AcceptedFeedsFormOneIntervalOnWhichTheCuspRises) {
  std::mt19937_64 engine(20);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 60; ++trial) {
    const double R = 2.0 + 98.0 * unit(engine);
    const double r = R * (0.05 + 0.9 * unit(engine));
    const int n = 1 + static_cast<int>(12.0 * unit(engine)) % 12;
    const MillingSense milling = trial % 2 == 0 ? kUp : kDown;
    const BoreMillingParams params = setup(R, r, n, milling);
    const double S_lim = bore_milling_feed_limit_mm(params);
    const double S_top = milling == kUp ? 2.0 * std::numbers::pi * (R - r) * n / (n + 2.0)
                                        : 2.0 * std::numbers::pi * std::min(R - r, r);
    SCOPED_TRACE(testing::Message() << "R " << R << " r " << r << " n " << n << " S_lim " << S_lim);
    double previous = 0.0;
    for (int i = 1; i <= 100; ++i) {
      const double S = S_lim * (i / 100.0);  // the last one S_lim itself
      ASSERT_TRUE(bore_milling_feed_accepted(at_feed(params, S))) << S;
      const double cusp = cusp_um(params, S);
      EXPECT_GT(cusp, previous) << S;
      previous = cusp;
    }
    for (int i = 1; i < 50; ++i) {
      const double S = S_lim + (S_top - S_lim) * i / 50.0;
      if (S <= S_lim * (1.0 + kRoundingNoise)) {
        continue;  // S_lim within a few doubles of S_top
      }
      EXPECT_FALSE(bore_milling_feed_accepted(at_feed(params, S))) << S;
    }
  }
}

}  // namespace
