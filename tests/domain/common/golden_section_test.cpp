#include "domain/common/golden_section.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cutcalc::domain {
namespace {

TEST(GoldenSection, FindsTheMinimumOfAUnimodalFunction) {
  const auto f = [](double x) { return std::abs(x - 0.3) + 2.0; };
  const GoldenSection s = golden_section_minimum(f, -1.0, 2.0, 1e-10, 200);
  EXPECT_LE(s.b - s.a, 1e-10);
  EXPECT_NEAR(s.midpoint(), 0.3, 1e-9);
  EXPECT_NEAR(s.smallest_value(), 2.0, 1e-10);
  EXPECT_LE(s.a, s.x1);
  EXPECT_LE(s.x1, s.x2);
  EXPECT_LE(s.x2, s.b);
}

TEST(GoldenSection, ShrinksTheBracketByTheGoldenRatioPerEvaluation) {
  int evaluations = 0;
  const auto f = [&](double x) {
    ++evaluations;
    return std::abs(x - 1.0);
  };
  const GoldenSection s = golden_section_minimum(f, 0.0, 3.0, 0.0, 30);
  EXPECT_EQ(evaluations, 32);  // the two inner points, then one per step
  EXPECT_NEAR(s.b - s.a, 3.0 * std::pow(0.5 * (std::sqrt(5.0) - 1.0), 30), 1e-12);
  EXPECT_NEAR(s.midpoint(), 1.0, 1e-5);
}

TEST(GoldenSection, StopsOnceTheBracketIsNarrowEnough) {
  int evaluations = 0;
  const auto f = [&](double x) {
    ++evaluations;
    return x * x;
  };
  const GoldenSection s = golden_section_minimum(f, -1.0, 1.0, 0.5, 100);
  // 2 * 0.618^2 = 0.764 > 0.5 >= 2 * 0.618^3 = 0.472: three steps.
  EXPECT_EQ(evaluations, 5);
  EXPECT_LE(s.b - s.a, 0.5);
}

TEST(GoldenSection, FindsAMaximumOfTheNegatedFunction) {
  const auto f = [](double x) { return -std::sin(x); };
  const GoldenSection s = golden_section_minimum(f, 0.0, 3.0, 1e-9, 200);
  // A smooth extremum is found to about sqrt(epsilon): the values beside it round alike.
  EXPECT_NEAR(s.midpoint(), 0.5 * std::acos(-1.0), 1e-7);
  EXPECT_NEAR(-s.smallest_value(), 1.0, 1e-15);
}

}  // namespace
}  // namespace cutcalc::domain
