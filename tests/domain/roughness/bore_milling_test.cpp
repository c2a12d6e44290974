// Bore-milling cusp, spec roughness.md part B: the worked example B.6, the errata tables B.7
// (Delta ~ f^2, Delta ~ 1/n^2), up against down, the approximation B8, and the rejections of B.4
// steps 1-4.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "domain/common/milling_sense.h"
#include "domain/common/result.h"
#include "domain/roughness/bore_milling.h"
#include "domain/roughness/roughness_test_support.h"

namespace {

using cutcalc::domain::ErrorCode;
using cutcalc::domain::MillingSense;
using cutcalc::domain::roughness::BoreMillingParams;
using cutcalc::domain::roughness::BoreMillingResult;
using cutcalc::domain::roughness::compute_bore_milling_cusp;

using cutcalc::test::roughness::kDown;
using cutcalc::test::roughness::kUp;

using cutcalc::test::roughness::bore_printed;

BoreMillingResult cusp(double R, double r, int n, double S, MillingSense milling) {
  const auto result = compute_bore_milling_cusp(BoreMillingParams{R, r, n, S, milling});
  EXPECT_TRUE(result.ok()) << "R " << R << " r " << r << " n " << n << " S " << S << ": "
                           << (result.ok() ? "" : result.error().detail);
  return result.ok() ? result.value() : BoreMillingResult{};
}

double cusp_mm(double R, double r, int n, double S, MillingSense milling = kUp) {
  return cusp(R, r, n, S, milling).cusp_height_um / 1000.0;
}

ErrorCode rejection(double R, double r, int n, double S, MillingSense milling) {
  const auto result = compute_bore_milling_cusp(BoreMillingParams{R, r, n, S, milling});
  EXPECT_FALSE(result.ok()) << "R " << R << " r " << r << " n " << n << " S " << S;
  if (result.ok()) {
    return ErrorCode::not_converged;  // any code the callers do not expect
  }
  EXPECT_FALSE(result.error().index.has_value());
  return result.error().code;
}

std::string rejection_detail(double R, double r, int n, double S, MillingSense milling) {
  const auto result = compute_bore_milling_cusp(BoreMillingParams{R, r, n, S, milling});
  return result.ok() ? std::string("accepted") : result.error().detail;
}

// B.6: the paper's Table 1 setting, up- and down-milling.
TEST(BoreMillingWorkedExample, PaperTableOneSetting) {
  const double R = 81.0;
  const double r = 32.4;
  EXPECT_NEAR(R / r, 2.5, 1e-15);
  const double Rc = R - r;
  EXPECT_NEAR(Rc, 48.6, 1e-12);
  EXPECT_NEAR(0.2 / (2.0 * std::numbers::pi * Rc), 6.55e-4, bore_printed(1e-6));  // eps (B1)

  const BoreMillingResult up = cusp(R, r, 4, 0.2, kUp);
  EXPECT_NEAR(up.feed_per_tooth_mm, 0.05, 1e-15);
  EXPECT_NEAR(up.feed_per_tooth_on_bore_mm, 0.083333, bore_printed(1e-6));
  EXPECT_NEAR(up.pitch_angle_deg, 0.058985, bore_printed(1e-6));
  EXPECT_NEAR(up.cusp_height_um, 0.0160436, bore_printed(1e-7));
  EXPECT_NEAR(up.approximate_cusp_height_um, 0.0160751, bore_printed(1e-7));
  EXPECT_NEAR(up.approximate_cusp_height_um / up.cusp_height_um - 1.0, 0.0020, bore_printed(1e-4));

  const BoreMillingResult down = cusp(R, r, 4, 0.2, kDown);
  EXPECT_NEAR(down.cusp_height_um, 0.0161067, bore_printed(1e-7));
  EXPECT_EQ(down.approximate_cusp_height_um, up.approximate_cusp_height_um);
  EXPECT_EQ(down.feed_per_tooth_mm, up.feed_per_tooth_mm);
  EXPECT_EQ(down.feed_per_tooth_on_bore_mm, up.feed_per_tooth_on_bore_mm);
  // B3: the kinematic spacing R alpha = f_zb / (1 - m eps) differs between the senses.
  EXPECT_LT(down.pitch_angle_deg, up.pitch_angle_deg);
}

// B.6: a small bore with a large feed, where the approximation is far off.
TEST(BoreMillingWorkedExample, SmallBoreLargeFeed) {
  const BoreMillingResult up = cusp(20.0, 8.0, 1, 2.0, kUp);
  EXPECT_NEAR(up.cusp_height_um, 96.402, bore_printed(1e-3));
  EXPECT_NEAR(up.approximate_cusp_height_um, 104.167, bore_printed(1e-3));
  EXPECT_NEAR(cusp(20.0, 8.0, 1, 2.0, kDown).cusp_height_um, 113.083, bore_printed(1e-3));

  const BoreMillingResult large = cusp(20.0, 8.0, 1, 5.0, kUp);
  EXPECT_NEAR(large.cusp_height_um, 539.96, bore_printed(1e-2));
  EXPECT_NEAR(large.approximate_cusp_height_um, 651.04, bore_printed(1e-2));
}

// B2, B3, B8 in closed form for a setting the spec does not print.
TEST(BoreMillingFeeds, ClosedFormOutputs) {
  const double R = 50.0;
  const double r = 10.0;
  const int n = 3;
  const double S = 0.9;
  const double Rc = R - r;
  const double eps = S / (2.0 * std::numbers::pi * Rc);
  for (const MillingSense milling : {kUp, kDown}) {
    const double m = milling == kUp ? 1.0 : -1.0;
    const BoreMillingResult v = cusp(R, r, n, S, milling);
    EXPECT_NEAR(v.feed_per_tooth_mm, 0.3, 1e-15);
    EXPECT_NEAR(v.feed_per_tooth_on_bore_mm, 0.3 * R / Rc, 1e-15);
    EXPECT_NEAR(v.pitch_angle_deg, 360.0 * std::abs(eps / (m - eps)) / n, 1e-13);
    const double f_zb = 0.3 * R / Rc;
    EXPECT_NEAR(v.approximate_cusp_height_um, 1000.0 * f_zb * f_zb / 8.0 * (1.0 / r - 1.0 / R),
                1e-12);
  }
}

// B-E4: the paper's Table 1 cannot be reproduced; the model's values for every reading, and the
// factor 4 (not 2.8) for a doubled feed.
TEST(BoreMillingErrata, TableOneFeedsOnTheCentrePath) {
  const double R = 81.0;
  const double r = 32.4;
  const double n4[] = {1.60e-5, 6.40e-5, 1.44e-4};
  const double n1[] = {2.57e-4, 1.02e-3, 2.30e-3};
  const double feeds[] = {0.2, 0.4, 0.6};
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(cusp_mm(R, r, 4, feeds[i]), n4[i], bore_printed(0.01 * n4[i]));
    EXPECT_NEAR(cusp_mm(R, r, 1, feeds[i]), n1[i], bore_printed(0.01 * n1[i]));
  }
  for (const int n : {1, 4}) {
    const double ratio = cusp_mm(R, r, n, 0.4) / cusp_mm(R, r, n, 0.2);
    EXPECT_GE(ratio, 3.985) << "n " << n;
    EXPECT_LE(ratio, 4.005) << "n " << n;
  }
}

TEST(BoreMillingErrata, TableOneFeedsMeasuredOnTheBore) {
  const double R = 81.0;
  const double r = 32.4;
  const double to_centre = (R - r) / R;  // B-E2: a feed on the bore is R/Rc times the centre's
  const double n4[] = {5.78e-6, 2.31e-5, 5.19e-5};
  const double n1[] = {9.25e-5, 3.69e-4, 8.30e-4};
  const double feeds[] = {0.2, 0.4, 0.6};
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(cusp_mm(R, r, 4, feeds[i] * to_centre), n4[i], bore_printed(0.01 * n4[i]));
    EXPECT_NEAR(cusp_mm(R, r, 1, feeds[i] * to_centre), n1[i], bore_printed(0.01 * n1[i]));
  }
  EXPECT_NEAR(cusp(R, r, 4, 0.2 * to_centre, kUp).feed_per_tooth_on_bore_mm, 0.05, 1e-15);
}

// B-E5: four teeth instead of one reduce the cusp 16x (Delta ~ 1/n^2), not 1.25x or 12.5x.
TEST(BoreMillingErrata, TableThreeTeeth) {
  const double R = 81.0;
  const double r = 32.4;
  EXPECT_NEAR(cusp_mm(R, r, 4, 0.2), 1.60e-5, bore_printed(1e-7));
  EXPECT_NEAR(cusp_mm(R, r, 2, 0.2), 6.42e-5, bore_printed(1e-7));
  EXPECT_NEAR(cusp_mm(R, r, 1, 0.2), 2.57e-4, bore_printed(1e-6));
  const double ratio = cusp_mm(R, r, 1, 0.2) / cusp_mm(R, r, 4, 0.2);
  EXPECT_NEAR(ratio, 16.0, 0.05);
}

// B-E6: Table 2's ratios R/r with r_d 81, S 0.2, n 4: monotone, +18 %.
TEST(BoreMillingErrata, TableTwoRadiusRatios) {
  const double ratios[] = {2.29, 2.61, 2.94, 3.38};
  const double expected[] = {1.566e-5, 1.629e-5, 1.715e-5, 1.847e-5};
  double previous = 0.0;
  for (int i = 0; i < 4; ++i) {
    const double value = cusp_mm(81.0, 81.0 / ratios[i], 4, 0.2);
    EXPECT_NEAR(value, expected[i], bore_printed(1e-8)) << "R/r " << ratios[i];
    EXPECT_GT(value, previous);
    previous = value;
  }
  EXPECT_NEAR(previous / cusp_mm(81.0, 81.0 / 2.29, 4, 0.2), 1.18, 0.005);
}

// Delta ~ f^2 and ~ 1/n^2 become exact as the feed vanishes (B-E4, B-E5).
TEST(BoreMillingScaling, QuadraticInTheFeedAndInverseSquareInTheTeeth) {
  for (const MillingSense milling : {kUp, kDown}) {
    for (const double ratio : {1.2, 2.5, 10.0}) {
      const double R = 40.0;
      const double r = R / ratio;
      const double S = 1e-4 * r;
      const double f2 = cusp_mm(R, r, 2, 2.0 * S, milling) / cusp_mm(R, r, 2, S, milling);
      EXPECT_NEAR(f2, 4.0, 1e-3) << "R/r " << ratio;
      const double n2 = cusp_mm(R, r, 3, S, milling) / cusp_mm(R, r, 6, S, milling);
      EXPECT_NEAR(n2, 4.0, 1e-3) << "R/r " << ratio;
    }
  }
}

// B8 is the small-feed limit of B5: up-milling lies below it and down-milling above, both by a
// relative amount that shrinks in proportion to the feed (observed: about S / (pi r) =
// n f_zb Rc / (pi R r), i.e. proportional to the orbit rate eps).
TEST(BoreMillingApproximation, CloseForSmallFeedsFromOppositeSides) {
  for (const double ratio : {1.1, 2.5, 10.0, 50.0}) {
    for (const int n : {1, 4, 12}) {
      const double R = 20.0;
      const double r = R / ratio;
      double previous_gap[2] = {0.0, 0.0};
      for (const double f_zb_over_r : {1e-2, 1e-3, 1e-4}) {
        const double S = f_zb_over_r * r * n * (R - r) / R;
        for (const MillingSense milling : {kUp, kDown}) {
          const BoreMillingResult v = cusp(R, r, n, S, milling);
          const double gap = v.cusp_height_um / v.approximate_cusp_height_um - 1.0;
          EXPECT_LT(std::abs(gap), 0.45 * n * f_zb_over_r * (R - r) / R)
              << "R/r " << ratio << " n " << n << " f_zb/r " << f_zb_over_r;
          if (milling == kUp) {
            EXPECT_LT(gap, 0.0) << "R/r " << ratio << " n " << n << " f_zb/r " << f_zb_over_r;
          } else {
            EXPECT_GT(gap, 0.0) << "R/r " << ratio << " n " << n << " f_zb/r " << f_zb_over_r;
          }
          const int i = milling == kUp ? 0 : 1;
          if (previous_gap[i] != 0.0) {
            EXPECT_NEAR(previous_gap[i] / gap, 10.0, 0.5) << "R/r " << ratio << " n " << n;
          }
          previous_gap[i] = gap;
        }
      }
    }
  }
}

// B.4 step 1 (the API checks r < R first and names /cutter_radius_mm; this is the backstop).
TEST(BoreMillingRejections, CutterNotSmallerThanBore) {
  EXPECT_EQ(rejection(20.0, 20.0, 2, 0.1, kUp), ErrorCode::cutter_not_smaller_than_bore);
  EXPECT_EQ(rejection(20.0, 25.0, 2, 0.1, kDown), ErrorCode::cutter_not_smaller_than_bore);
  EXPECT_EQ(rejection(1.0, std::nextafter(1.0, 2.0), 1, 1e-3, kUp),
            ErrorCode::cutter_not_smaller_than_bore);
  // The largest cutter below the bore is still a valid tool, with a tiny centre circle.
  const auto tight =
      compute_bore_milling_cusp(BoreMillingParams{1.0, std::nextafter(1.0, 0.0), 1, 1e-18, kUp});
  ASSERT_TRUE(tight.ok()) << tight.error().detail;
  EXPECT_TRUE(std::isfinite(tight.value().cusp_height_um));
}

// B.4 step 2: eps >= 1.
TEST(BoreMillingRejections, CentreOrbitsFasterThanTheSpindle) {
  const double Rc = 12.0;
  const double one_orbit = 2.0 * std::numbers::pi * Rc;  // S giving eps = 1 exactly
  for (const MillingSense milling : {kUp, kDown}) {
    for (const int n : {1, 8, 1000}) {
      EXPECT_EQ(rejection(20.0, 8.0, n, one_orbit, milling), ErrorCode::bore_feed_too_large);
      EXPECT_EQ(rejection(20.0, 8.0, n, 3.0 * one_orbit, milling), ErrorCode::bore_feed_too_large);
    }
  }
  EXPECT_NE(rejection_detail(20.0, 8.0, 1000, one_orbit, kUp).find("orbit"), std::string::npos);
}

// B.4 step 2: alpha >= 180 deg, tested as 2 eps >= n |m - eps|; exactly 180 deg is rejected.
TEST(BoreMillingRejections, PitchAngleOfHalfATurn) {
  EXPECT_EQ(rejection(20.0, 8.0, 1, 30.0, kUp), ErrorCode::bore_feed_too_large);  // reference
  EXPECT_NE(rejection_detail(20.0, 8.0, 1, 30.0, kUp).find("180"), std::string::npos);
  // Up, n = 2: 2 eps = 2 (1 - eps) at eps = 1/2, i.e. S = pi Rc (exact in doubles).
  const double Rc = 12.0;
  const double half_orbit = std::numbers::pi * Rc;
  EXPECT_NE(rejection_detail(20.0, 8.0, 2, half_orbit, kUp).find("180"), std::string::npos);
  EXPECT_EQ(rejection_detail(20.0, 8.0, 2, std::nextafter(half_orbit, 0.0), kUp).find("180"),
            std::string::npos);
  // Down, n = 1: 2 eps = 1 + eps at eps = 1, which step 2 already rejects; n = 1 down never
  // reaches 180 deg otherwise.
  EXPECT_EQ(rejection_detail(20.0, 8.0, 1, 0.99 * 2.0 * half_orbit, kDown).find("180"),
            std::string::npos);
}

// B.4 step 3: down-milling with S = 2 pi r exactly leaves the tooth at rest on the bore.
TEST(BoreMillingRejections, ToothAtRestOnTheBore) {
  // R 5, r 1: eps = 1/4 and k + r/R = -0.2 + 0.2 = 0 exactly in doubles.
  const double S = 2.0 * std::numbers::pi * 1.0;
  EXPECT_EQ(rejection(5.0, 1.0, 1, S, kDown), ErrorCode::bore_feed_too_large);
  EXPECT_NE(rejection_detail(5.0, 1.0, 1, S, kDown).find("rest"), std::string::npos);
  // Up-milling with the same feed is an ordinary (large) feed.
  EXPECT_EQ(rejection_detail(5.0, 1.0, 1, S, kUp).find("rest"), std::string::npos);
  // Beside the singular feed the answer is either a finite cusp or a rejection, never garbage.
  for (const double factor : {1.0 - 1e-6, 1.0 - 1e-12, 1.0 + 1e-12, 1.0 + 1e-6}) {
    const auto near = compute_bore_milling_cusp(BoreMillingParams{5.0, 1.0, 4, S * factor, kDown});
    if (near.ok()) {
      EXPECT_TRUE(std::isfinite(near.value().cusp_height_um));
      EXPECT_GE(near.value().cusp_height_um, 0.0);
      EXPECT_LT(near.value().cusp_height_um, 1000.0 * 2.0);  // within the cutter diameter
    } else {
      EXPECT_EQ(near.error().code, ErrorCode::bore_feed_too_large);
    }
  }
}

// B.4 step 4: the paths meet only beyond the monotone part (the research code's 4.77 mm cusp of
// a 3 mm cutter), for pi/2 and for delta_m as the bracket end.
TEST(BoreMillingRejections, PathsDoNotMeetOnTheMonotonePart) {
  EXPECT_EQ(rejection(81.0, 3.0, 2, 25.0, kDown), ErrorCode::bore_feed_too_large);
  EXPECT_NE(rejection_detail(81.0, 3.0, 2, 25.0, kDown).find("90 degrees"), std::string::npos);
  // Up-milling, hi = pi/2: f_zb of several cutter radii.
  EXPECT_NE(rejection_detail(20.0, 2.0, 1, 12.0, kUp).find("90 degrees"), std::string::npos);
  // Just inside the domain: a large but admissible feed gives a cusp below the cutter radius.
  const BoreMillingResult v = cusp(20.0, 2.0, 1, 4.0, kUp);
  EXPECT_GT(v.cusp_height_um, 0.0);
  EXPECT_LT(v.cusp_height_um, 2000.0);
}

// The case where the research code's bracket expansion failed is inside this procedure's domain.
TEST(BoreMillingRejections, ResearchBracketFailureIsAnOrdinaryCase) {
  const BoreMillingResult v = cusp(16.0, 0.75, 11, 3.08, kDown);
  EXPECT_GT(v.cusp_height_um, 0.0);
  EXPECT_LT(v.cusp_height_um, 750.0);
}

// Extreme but valid magnitudes: finite, non-negative, never NaN.
TEST(BoreMillingRobustness, ExtremeMagnitudesStayFinite) {
  const BoreMillingParams cases[] = {
      {81.0, 32.4, 4, 1e-300, kUp},     {81.0, 32.4, 4, 5e-324, kDown},
      {1e-200, 4e-201, 2, 1e-203, kUp}, {1e200, 4e199, 2, 1e197, kDown},
      {1e300, 1e290, 3, 1e285, kUp},    {1e6, 1.0, 1000, 1.0, kDown},
      {81.0, 1e-9, 1, 1e-12, kDown},    {81.0, 81.0 - 1e-9, 1, 1e-12, kUp},
  };
  for (const BoreMillingParams& p : cases) {
    const auto result = compute_bore_milling_cusp(p);
    ASSERT_TRUE(result.ok()) << "R " << p.bore_radius_mm << " r " << p.cutter_radius_mm << " S "
                             << p.feed_per_rev_mm << ": " << result.error().detail;
    const BoreMillingResult& v = result.value();
    for (const double x : {v.cusp_height_um, v.approximate_cusp_height_um, v.feed_per_tooth_mm,
                           v.feed_per_tooth_on_bore_mm, v.pitch_angle_deg}) {
      EXPECT_TRUE(std::isfinite(x));
      EXPECT_GE(x, 0.0);
    }
    EXPECT_LE(v.cusp_height_um, 1000.0 * 2.0 * p.cutter_radius_mm);
  }
}

// Radii near the top of the double range: a cusp beyond 1.8e308 um is an error, not an infinity.
TEST(BoreMillingRobustness, OverflowingCuspHeightIsAnError) {
  const double R = 1.5e308;
  const double r = 1e308;
  const double S = 0.5 * r * ((R - r) / R);  // f_zb = r / 2: a cusp of about r / 100
  const auto result = compute_bore_milling_cusp(BoreMillingParams{R, r, 1, S, kUp});
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().code, ErrorCode::not_converged);
  // With a small feed the same radii are representable throughout, and 2 pi Rc overflowing must
  // not make the orbit rate 0: the cusp scales with the lengths.
  const double S_small = 1e-3 * r * ((R - r) / R);
  const auto huge = compute_bore_milling_cusp(BoreMillingParams{R, r, 1, S_small, kUp});
  const auto scaled =
      compute_bore_milling_cusp(BoreMillingParams{R / 1e10, r / 1e10, 1, S_small / 1e10, kUp});
  ASSERT_TRUE(huge.ok() && scaled.ok());
  EXPECT_NEAR(huge.value().cusp_height_um / scaled.value().cusp_height_um, 1e10, 1e-9 * 1e10);
  EXPECT_NEAR(huge.value().pitch_angle_deg, scaled.value().pitch_angle_deg,
              1e-12 * scaled.value().pitch_angle_deg);
}

}  // namespace
