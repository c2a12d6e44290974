// K15-K16 (grooving-cycle.md 3.5): minutes per revolution at a diameter, and their mean over a
// radial move, against the definition: 1/n(D) written out here and integrated numerically.

#include "domain/grooving/revolution_time.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>

namespace cutcalc::domain::grooving {
namespace {

constexpr double kCuttingSpeed = 86.0;  // v, m/min (the paper's)
constexpr double kMaxRpm = 1000.0;      // n_max
// D* = 1000 v / (pi n_max) = 27.3747... mm: below it G96 runs at n_max.
const double kClampDiameter = 1000.0 * kCuttingSpeed / (std::numbers::pi * kMaxRpm);

SpindleMode css() { return {std::nullopt, kCuttingSpeed, kMaxRpm}; }
SpindleMode constant(double rpm) { return {rpm, std::nullopt, std::nullopt}; }

// 1/n(D) of K15 under G96, written from the definition n = min(n_max, 1000 v / (pi D)).
double definition(double d_mm) {
  return 1.0 / std::min(kMaxRpm, 1000.0 * kCuttingSpeed / (std::numbers::pi * d_mm));
}

// The mean of 1/n(D) over [lo, hi] by the midpoint rule (exact on each linear piece; the kink at
// D* costs O(step^2)).
double numerical_mean(double lo, double hi) {
  constexpr int kSteps = 200000;
  const double step = (hi - lo) / kSteps;
  double sum = 0.0;
  for (int i = 0; i < kSteps; ++i) sum += definition(lo + (i + 0.5) * step);
  return sum * step / (hi - lo);
}

TEST(RevolutionTime, ConstantSpeedIsOneOverNAtEveryDiameter) {
  // K15, G97: the diameter does not matter, nor does a max_spindle_rpm given as a warning limit.
  const SpindleMode g97{500.0, std::nullopt, 400.0};
  for (const double d : {1.0, 27.0, 220.0}) {
    EXPECT_NEAR(minutes_per_revolution(g97, d), 1.0 / 500.0, 1e-15) << d;
  }
  // K16: the mean is 1/n too, in either order.
  EXPECT_NEAR(mean_minutes_per_revolution(constant(125.0), 220.0, 210.4), 0.008, 1e-15);
  EXPECT_NEAR(mean_minutes_per_revolution(constant(125.0), 10.0, 300.0), 0.008, 1e-15);
}

TEST(RevolutionTime, ConstantSurfaceSpeedFollowsTheDiameterUntilTheLimit) {
  // K15: pi D / (1000 v) above D*, 1/n_max below it.
  EXPECT_NEAR(minutes_per_revolution(css(), 220.0), std::numbers::pi * 220.0 / 86000.0, 1e-15);
  EXPECT_NEAR(minutes_per_revolution(css(), 10.0), 1.0 / kMaxRpm, 1e-15);
  EXPECT_NEAR(clamp_diameter_mm(css()), kClampDiameter, 1e-12);
  EXPECT_NEAR(minutes_per_revolution(css(), kClampDiameter), 1.0 / kMaxRpm, 1e-15);
  // The worked example's spindle speeds (section 7): n(220) = 124.430, n(210.4) = 130.108 rpm.
  EXPECT_NEAR(1.0 / minutes_per_revolution(css(), 220.0), 124.430, 0.5e-3);
  EXPECT_NEAR(1.0 / minutes_per_revolution(css(), 210.4), 130.108, 0.5e-3);
}

TEST(RevolutionTime, MeanBelowTheClampDiameterIsOneOverNMax) {
  // K16 branch hi <= D*.
  const double got = mean_minutes_per_revolution(css(), 10.0, 25.0);
  EXPECT_NEAR(got, 1.0 / kMaxRpm, 1e-15);
  EXPECT_NEAR(got, numerical_mean(10.0, 25.0), 1e-12);
  // hi exactly D*.
  EXPECT_NEAR(mean_minutes_per_revolution(css(), 5.0, kClampDiameter), 1.0 / kMaxRpm, 1e-15);
}

TEST(RevolutionTime, MeanAboveTheClampDiameterIsTheMidDiameterValue) {
  // K16 branch lo >= D*: k (lo + hi) / 2.
  const double got = mean_minutes_per_revolution(css(), 220.0, 210.4);
  EXPECT_NEAR(got, std::numbers::pi * 215.2 / 86000.0, 1e-15);
  EXPECT_NEAR(got, numerical_mean(210.4, 220.0), 1e-9 * got);
}

TEST(RevolutionTime, MeanAcrossTheClampDiameterMatchesTheIntegral) {
  // K16 branch lo < D* < hi: the two pieces weighted by their lengths.
  const double got = mean_minutes_per_revolution(css(), 40.0, 20.0);
  EXPECT_NEAR(got, numerical_mean(20.0, 40.0), 1e-9 * got);
  // Above both pure branches' values (1/n(D) >= each of them), below 1/n(hi).
  EXPECT_GT(got, 1.0 / kMaxRpm);
  EXPECT_GT(got, std::numbers::pi * 30.0 / 86000.0);
  EXPECT_LT(got, std::numbers::pi * 40.0 / 86000.0);
  // Either order.
  EXPECT_EQ(got, mean_minutes_per_revolution(css(), 20.0, 40.0));
}

TEST(RevolutionTime, MeanOverAZeroLengthMoveIsTheValueThere) {
  // K16: lo == hi (a Z-only block) -> 1/n(lo), on both sides of D*.
  EXPECT_NEAR(mean_minutes_per_revolution(css(), 210.4, 210.4), std::numbers::pi * 210.4 / 86000.0,
              1e-15);
  EXPECT_NEAR(mean_minutes_per_revolution(css(), 12.0, 12.0), 1.0 / kMaxRpm, 1e-15);
}

}  // namespace
}  // namespace cutcalc::domain::grooving
