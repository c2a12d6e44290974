// The shared numeric facts of domain/common/numeric.h that are not covered by a family's tests:
// the count guard and the two-rounding angle forms that keep printed results as they were.

#include "domain/common/numeric.h"

#include <gtest/gtest.h>

#include <numbers>

namespace cutcalc::domain {
namespace {

TEST(CeilCount, AQuotientRoundedJustAboveAWholeNumberCountsAsThatNumber) {
  ASSERT_GT(0.07 / 0.01, 7.0);  // the floating noise the guard is for
  EXPECT_EQ(ceil_count(0.07 / 0.01), 7.0);
  EXPECT_EQ(ceil_count(7.0), 7.0);
}

TEST(CeilCount, AnyPartOfAPassBeyondTheGuardIsOneMore) {
  EXPECT_EQ(ceil_count(7.000001), 8.0);
  EXPECT_EQ(ceil_count(2.5), 3.0);
}

TEST(CeilCount, AtLeastOneEvenForAVanishingQuotient) {
  EXPECT_EQ(ceil_count(1e-12), 1.0);
  EXPECT_EQ(ceil_count(0.0), 1.0);
}

TEST(AngleConversion, TwoRoundingFormsDifferFromTheOneRoundingFormsInTheLastBit) {
  // Why numeric.h keeps both forms: swapping one for the other changes these angles.
  EXPECT_NE(rad_times_180_over_pi(0.1), rad_to_deg(0.1));
  EXPECT_EQ(rad_times_180_over_pi(0.1), 0.1 * 180.0 / std::numbers::pi);
  EXPECT_NE(deg_times_pi_over_180(3.0), deg_to_rad(3.0));
  EXPECT_EQ(deg_times_pi_over_180(3.0), 3.0 * std::numbers::pi / 180.0);
  EXPECT_NEAR(deg_times_pi_over_180(90.0), 0.5 * std::numbers::pi, 1e-15);
}

}  // namespace
}  // namespace cutcalc::domain
