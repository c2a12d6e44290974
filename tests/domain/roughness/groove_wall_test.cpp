// Groove side wall crest height, spec roughness.md part R: the worked example R.5, the errata
// R.6, the branch limits and their continuity (R2, R6), phi1 = 0, and an independent check
// against the raw tool outlines of R.3.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "domain/common/numeric.h"
#include "domain/common/result.h"
#include "domain/roughness/crest_branches.h"
#include "domain/roughness/groove_wall.h"
#include "domain/roughness/roughness_test_support.h"

namespace {

using cutcalc::domain::ErrorCode;
using cutcalc::domain::roughness::compute_groove_wall_roughness;
using cutcalc::domain::roughness::CrestBranch;
using cutcalc::domain::roughness::GrooveWallParams;
using cutcalc::domain::roughness::GrooveWallResult;
namespace roughness_detail = cutcalc::domain::roughness::detail;

using cutcalc::domain::kRadPerDeg;

using cutcalc::test::roughness::wall_printed;

GrooveWallResult groove(double S, double rho, double phi1_deg) {
  const auto result = compute_groove_wall_roughness(GrooveWallParams{S, rho, phi1_deg, {}});
  EXPECT_TRUE(result.ok()) << "S " << S << " rho " << rho << " phi1 " << phi1_deg;
  return result.ok() ? result.value() : GrooveWallResult{};
}

double rz_um(double S, double rho, double phi1_deg) { return groove(S, rho, phi1_deg).rz_um; }

// Paper eq. (6) exactly as printed (NaN where its square root is negative): the law the errata
// R-E1 and R-E2 correct.
double paper_eq6_um(double S, double rho, double phi1_deg) {
  const double phi1 = phi1_deg * kRadPerDeg;
  const double radicand = S * std::sin(phi1) * (2.0 * rho - S * std::sin(phi1));
  return 1000.0 * (rho * (1.0 - std::cos(phi1)) +
                   std::sin(phi1) * (S * std::cos(phi1) - std::sqrt(radicand)));
}

// Independent oracle (R.3): the tool's upper boundary, the wall as the upper envelope of the
// previous (x + S) and current boundaries, the crest where they cross, found by bisection in long
// double. No branch formula is used.
using cutcalc::test::roughness::tool_boundary;

double oracle_rz_um(double S_in, double rho_in, double phi1_deg) {
  const long double S = S_in;
  const long double rho = rho_in;
  const long double phi1 = static_cast<long double>(phi1_deg) * 3.14159265358979323846264338L / 180;
  // previous minus current boundary: >= 0 at x = -S, <= 0 at x = 0, decreasing in between.
  long double lo = -S;
  long double hi = 0.0L;
  for (int i = 0; i < 400 && lo < hi; ++i) {
    const long double mid = 0.5L * (lo + hi);
    if (mid == lo || mid == hi) {
      break;
    }
    const long double gap = tool_boundary(mid + S, rho, phi1) - tool_boundary(mid, rho, phi1);
    (gap > 0 ? lo : hi) = mid;
  }
  // The lowest point of the envelope on either side of the crossing; in branch C the crossing is
  // the previous main edge, a vertical step, and only its right side is the crest.
  auto envelope = [&](long double x) {
    return std::max(tool_boundary(x + S, rho, phi1), tool_boundary(x, rho, phi1));
  };
  const long double z_c = std::min(envelope(lo), envelope(hi));
  return static_cast<double>(1000.0L * (rho - z_c));
}

// R.5, phi1 = 2 deg: branch limits, Fig. 5 feeds, the "v razvod" pitch and the target.
TEST(GrooveWallWorkedExample, PaperGeometryMinorEdgeTwoDegrees) {
  const double rho = 0.3;
  const auto phi1 = roughness_detail::minor_edge_angle(2.0 * kRadPerDeg);
  const auto limits = roughness_detail::branch_limits(rho, phi1);
  EXPECT_NEAR(limits.S_AB, 0.020940, wall_printed(1e-6));
  EXPECT_NEAR(limits.S_BC, 8.8961, wall_printed(1e-4));
  EXPECT_NEAR(2.0 * rho / phi1.sin_phi1, 17.192, wall_printed(1e-3));  // end of eq. (6)'s domain

  const double feeds[] = {0.08, 0.12, 0.16, 0.20};
  const double expected_um[] = {1.5479, 2.6248, 3.7526, 4.9131};
  for (int i = 0; i < 4; ++i) {
    const GrooveWallResult r = groove(feeds[i], rho, 2.0);
    EXPECT_NEAR(r.rz_um, expected_um[i], wall_printed(1e-4)) << "S " << feeds[i];
    EXPECT_EQ(r.branch, CrestBranch::nose_arc_and_minor_edge) << "S " << feeds[i];
    EXPECT_FALSE(r.max_feed_mm.has_value());
  }
  EXPECT_NEAR(rz_um(0.48, rho, 2.0), 13.4746, wall_printed(1e-4));  // pitch 4 S0, S0 = 0.12

  const auto with_target = compute_groove_wall_roughness(GrooveWallParams{0.12, rho, 2.0, 13.2});
  ASSERT_TRUE(with_target.ok());
  EXPECT_NEAR(with_target.value().rz_um, 2.6248, wall_printed(1e-4));
  EXPECT_EQ(with_target.value().branch, CrestBranch::nose_arc_and_minor_edge);
  ASSERT_TRUE(with_target.value().max_feed_mm.has_value());
  EXPECT_NEAR(*with_target.value().max_feed_mm, 0.471245, wall_printed(1e-6));
}

// R.5, phi1 = 30 deg: the same feeds lie in branch A (two nose arcs).
TEST(GrooveWallWorkedExample, PaperGeometryMinorEdgeThirtyDegrees) {
  const double feeds[] = {0.08, 0.12, 0.16, 0.20};
  const double expected_um[] = {2.6786, 6.0612, 10.8634, 17.1573};
  for (int i = 0; i < 4; ++i) {
    const GrooveWallResult r = groove(feeds[i], 0.3, 30.0);
    EXPECT_NEAR(r.rz_um, expected_um[i], wall_printed(1e-4)) << "S " << feeds[i];
    EXPECT_EQ(r.branch, CrestBranch::nose_arc) << "S " << feeds[i];
  }
}

// R-E1: eq. (6) below S_AB is wrong; the crest lies between two nose arcs (R3).
TEST(GrooveWallErrata, PaperEquationSixBelowNoseArcLimit) {
  EXPECT_NEAR(paper_eq6_um(0.08, 0.3, 30.0), 0.000247, wall_printed(1e-6));
  EXPECT_NEAR(rz_um(0.08, 0.3, 30.0), 2.6786, wall_printed(1e-4));
  EXPECT_EQ(groove(0.08, 0.3, 30.0).branch, CrestBranch::nose_arc);

  EXPECT_NEAR(paper_eq6_um(0.08, 0.3, 10.0), 2.5696, wall_printed(1e-4));
  EXPECT_NEAR(rz_um(0.08, 0.3, 10.0), 2.6786, wall_printed(1e-4));
  EXPECT_EQ(groove(0.08, 0.3, 10.0).branch, CrestBranch::nose_arc);

  EXPECT_NEAR(paper_eq6_um(0.05, 0.4, 45.0), 25.894, wall_printed(1e-3));
  EXPECT_NEAR(rz_um(0.05, 0.4, 45.0), 0.7820, wall_printed(1e-4));
  EXPECT_EQ(groove(0.05, 0.4, 45.0).branch, CrestBranch::nose_arc);
}

// R-E2: above S_BC the crest is on the main edge (R5); eq. (6) is off, then undefined.
TEST(GrooveWallErrata, PaperEquationSixAboveMainEdgeLimit) {
  EXPECT_NEAR(paper_eq6_um(10.0, 0.3, 2.0), 338.636, wall_printed(1e-3));
  const GrooveWallResult at10 = groove(10.0, 0.3, 2.0);
  EXPECT_NEAR(at10.rz_um, 338.549, wall_printed(1e-3));
  EXPECT_EQ(at10.branch, CrestBranch::minor_edge_and_main_edge);

  EXPECT_TRUE(std::isnan(paper_eq6_um(20.0, 0.3, 2.0)));
  const GrooveWallResult at20 = groove(20.0, 0.3, 2.0);
  EXPECT_NEAR(at20.rz_um, 687.756, wall_printed(1e-3));
  EXPECT_EQ(at20.branch, CrestBranch::minor_edge_and_main_edge);
}

// R-E3: the OCR'd eq. (5) of scheme 1a is eq. (6) with the pitch 4 S0, not a separate law.
TEST(GrooveWallErrata, SchemeOneAIsEquationSixWithFourTimesTheFeed) {
  const double rho = 0.3;
  const double S0 = 0.12;
  const double phi1 = 2.0 * kRadPerDeg;
  const double eq5_um =
      1000.0 * (rho * (1.0 - std::cos(phi1)) +
                4.0 * std::sin(phi1) *
                    (S0 * std::cos(phi1) -
                     std::sqrt(S0 * std::sin(phi1) * (rho / 2.0 - S0 * std::sin(phi1)))));
  EXPECT_NEAR(eq5_um, 13.4746, wall_printed(1e-4));
  EXPECT_NEAR(rz_um(4.0 * S0, rho, 2.0), eq5_um, 1e-9 * eq5_um);
}

// One-sided second-order difference quotients.
template <class F>
double left_slope(const F& f, double x, double h) {
  return (3.0 * f(x) - 4.0 * f(x - h) + f(x - 2.0 * h)) / (2.0 * h);
}

template <class F>
double right_slope(const F& f, double x, double h) {
  return (-3.0 * f(x) + 4.0 * f(x + h) - f(x + 2.0 * h)) / (2.0 * h);
}

// R2 with the inferred rule: a limit value belongs to the lower branch.
TEST(GrooveWallBranches, LimitValuesBelongToTheLowerBranch) {
  for (const double phi1_deg : {0.5, 2.0, 10.0, 30.0, 45.0, 60.0, 80.0, 89.0}) {
    for (const double rho : {0.1, 0.3, 1.2}) {
      const auto limits = roughness_detail::branch_limits(
          rho, roughness_detail::minor_edge_angle(phi1_deg * kRadPerDeg));
      const double inf = std::numeric_limits<double>::infinity();
      EXPECT_EQ(groove(limits.S_AB, rho, phi1_deg).branch, CrestBranch::nose_arc);
      EXPECT_EQ(groove(std::nextafter(limits.S_AB, inf), rho, phi1_deg).branch,
                CrestBranch::nose_arc_and_minor_edge);
      EXPECT_EQ(groove(limits.S_BC, rho, phi1_deg).branch, CrestBranch::nose_arc_and_minor_edge);
      EXPECT_EQ(groove(std::nextafter(limits.S_BC, inf), rho, phi1_deg).branch,
                CrestBranch::minor_edge_and_main_edge);
      EXPECT_EQ(groove(std::nextafter(limits.S_AB, 0.0), rho, phi1_deg).branch,
                CrestBranch::nose_arc);
    }
  }
}

// R6: both neighbouring branch formulas give rho (1 - cos phi1) at S_AB and rho at S_BC, and the
// slopes agree there too (R7: Rz is C1).
TEST(GrooveWallBranches, ContinuousWithContinuousSlopeAtTheLimits) {
  for (const double phi1_deg : {0.01, 0.5, 2.0, 10.0, 30.0, 45.0, 60.0, 80.0, 89.0, 89.9}) {
    for (const double rho : {0.1, 0.3, 0.8, 1.2}) {
      const double phi1_rad = phi1_deg * kRadPerDeg;
      const auto phi1 = roughness_detail::minor_edge_angle(phi1_rad);
      const auto limits = roughness_detail::branch_limits(rho, phi1);
      const double at_AB = rho * (1.0 - std::cos(phi1_rad));  // rounding of 1 - cos is ~1e-16
      const double tol_AB = 1e-12 * at_AB + 2e-16 * rho;
      EXPECT_NEAR(roughness_detail::crest_height_nose_arc(limits.S_AB, rho), at_AB, tol_AB);
      EXPECT_NEAR(
          roughness_detail::crest_height_nose_arc_and_minor_edge(limits.S_AB, rho, phi1, limits),
          at_AB, tol_AB);
      EXPECT_NEAR(
          roughness_detail::crest_height_nose_arc_and_minor_edge(limits.S_BC, rho, phi1, limits),
          rho, 1e-12 * rho);
      EXPECT_NEAR(
          roughness_detail::crest_height_minor_edge_and_main_edge(limits.S_BC, rho, phi1, limits),
          rho, 1e-12 * rho);

      // Second-order one-sided difference quotients of the neighbouring branches at each limit,
      // with steps well inside the distance rho cos^2(phi1) to the singular S = 2 rho.
      const double h = 1e-5 * std::min(limits.S_AB, rho * phi1.cos_phi1 * phi1.cos_phi1);
      const auto A = [&](double S) { return roughness_detail::crest_height_nose_arc(S, rho); };
      const auto B = [&](double S) {
        return roughness_detail::crest_height_nose_arc_and_minor_edge(S, rho, phi1, limits);
      };
      const double slope_A = left_slope(A, limits.S_AB, h);
      const double slope_B_at_AB = right_slope(B, limits.S_AB, h);
      EXPECT_NEAR(slope_A, 0.5 * phi1.tan_phi1, 1e-4 * phi1.tan_phi1) << "phi1 " << phi1_deg;
      EXPECT_NEAR(slope_B_at_AB, slope_A, 1e-4 * phi1.tan_phi1) << "phi1 " << phi1_deg;
      const double h_BC = 1e-5 * rho * phi1.cos_phi1 * phi1.cos_phi1;
      const double slope_B_at_BC = left_slope(B, limits.S_BC, h_BC);
      EXPECT_NEAR(slope_B_at_BC, phi1.tan_phi1, 1e-4 * phi1.tan_phi1) << "phi1 " << phi1_deg;
    }
  }
}

// The public function on either side of each limit: no jump larger than the true increase.
TEST(GrooveWallBranches, PublicValueContinuousAcrossTheLimits) {
  for (const double phi1_deg : {0.5, 2.0, 30.0, 60.0, 89.0}) {
    const double rho = 0.3;
    const auto phi1 = roughness_detail::minor_edge_angle(phi1_deg * kRadPerDeg);
    const auto limits = roughness_detail::branch_limits(rho, phi1);
    for (const double S_limit : {limits.S_AB, limits.S_BC}) {
      const double below = rz_um(S_limit * (1.0 - 1e-12), rho, phi1_deg);
      const double above = rz_um(S_limit * (1.0 + 1e-12), rho, phi1_deg);
      // The slope is at most tan(phi1) at both limits (R7), so the step is 2e-12 S tan(phi1).
      const double allowed = 1000.0 * 2e-12 * S_limit * phi1.tan_phi1 + 1e-12 * below;
      EXPECT_GE(above, below) << "phi1 " << phi1_deg << " S " << S_limit;
      EXPECT_LE(above - below, allowed) << "phi1 " << phi1_deg << " S " << S_limit;
    }
  }
}

// R4 with phi1 = 0: the minor edge lies on the wall, Rz = 0 at every feed; a target is refused.
TEST(GrooveWallMinorEdgeZero, CrestHeightIsZeroAtEveryFeed) {
  for (const double S : {1e-6, 0.01, 0.12, 0.6, 5.0, 50.0, 1e6}) {
    for (const double rho : {0.05, 0.3, 2.0}) {
      const GrooveWallResult r = groove(S, rho, 0.0);
      EXPECT_EQ(r.rz_um, 0.0);
      EXPECT_EQ(r.branch, CrestBranch::nose_arc_and_minor_edge);
      EXPECT_FALSE(r.max_feed_mm.has_value());
    }
  }
}

TEST(GrooveWallMinorEdgeZero, TargetIsRejected) {
  const auto result = compute_groove_wall_roughness(GrooveWallParams{0.1, 0.3, 0.0, 5.0});
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().code, ErrorCode::target_needs_minor_edge_angle);
  EXPECT_FALSE(result.error().index.has_value());
}

// An angle that vanishes in the conversion to radians is 0; one that survives it but makes the
// maximum feed overflow is refused the same way; neither yields an infinity.
TEST(GrooveWallMinorEdgeZero, VanishingAnglesGiveFiniteAnswersOrTheSameError) {
  const GrooveWallResult underflow = groove(0.1, 0.3, 1e-323);
  EXPECT_EQ(underflow.rz_um, 0.0);
  const auto with_target = compute_groove_wall_roughness(GrooveWallParams{0.1, 0.3, 1e-323, 5.0});
  ASSERT_FALSE(with_target.ok());
  EXPECT_EQ(with_target.error().code, ErrorCode::target_needs_minor_edge_angle);

  const auto overflow = compute_groove_wall_roughness(GrooveWallParams{0.1, 0.3, 1e-310, 5.0});
  ASSERT_FALSE(overflow.ok());
  EXPECT_EQ(overflow.error().code, ErrorCode::target_needs_minor_edge_angle);
  const GrooveWallResult tiny = groove(0.1, 0.3, 1e-310);
  EXPECT_TRUE(std::isfinite(tiny.rz_um));
  EXPECT_GE(tiny.rz_um, 0.0);

  const auto small = compute_groove_wall_roughness(GrooveWallParams{0.1, 0.3, 1e-300, 5.0});
  ASSERT_TRUE(small.ok());
  ASSERT_TRUE(small.value().max_feed_mm.has_value());
  EXPECT_TRUE(std::isfinite(*small.value().max_feed_mm));
}

// Near 90 deg the minor edge is almost the main edge: the values stay finite and positive.
TEST(GrooveWallBranches, SteepMinorEdgeStaysFinite) {
  const double phi1_deg = std::nextafter(90.0, 0.0);
  for (const double S : {1e-4, 0.3, 0.6, 1.0, 100.0, 1e6}) {
    const GrooveWallResult r = groove(S, 0.3, phi1_deg);
    EXPECT_TRUE(std::isfinite(r.rz_um)) << "S " << S;
    EXPECT_GT(r.rz_um, 0.0) << "S " << S;
  }
}

// Only an absurd pitch overflows the micrometres; the answer is an error, never an infinity.
TEST(GrooveWallBranches, OverflowingCrestHeightIsAnError) {
  const auto result = compute_groove_wall_roughness(
      GrooveWallParams{1e300, 0.3, std::nextafter(90.0, 0.0), std::nullopt});
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().code, ErrorCode::not_converged);
}

// R3-R5 against the raw outlines of R.3 over random valid inputs, in all three branches.
TEST(GrooveWallOracle, MatchesTheIntersectionOfTheToolOutlines) {
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int counts[3] = {0, 0, 0};
  for (int i = 0; i < 3000; ++i) {
    const double rho = 0.05 * std::pow(40.0, unit(rng));     // 0.05 .. 2 mm
    const double phi1_deg = 0.1 + 89.7 * unit(rng);          // 0.1 .. 89.8 deg
    const double S = 1e-3 * rho * std::pow(1e5, unit(rng));  // 1e-3 rho .. 100 rho
    const GrooveWallResult r = groove(S, rho, phi1_deg);
    ++counts[static_cast<int>(r.branch)];
    const double want = oracle_rz_um(S, rho, phi1_deg);
    EXPECT_NEAR(r.rz_um, want, 1e-10 * want + 1e-12)
        << "rho " << rho << " phi1 " << phi1_deg << " S " << S;
  }
  EXPECT_GT(counts[0], 100);
  EXPECT_GT(counts[1], 100);
  EXPECT_GT(counts[2], 100);
}

// The oracle itself reproduces the printed numbers, so it is not trivially wrong.
TEST(GrooveWallOracle, ReproducesTheWorkedExample) {
  EXPECT_NEAR(oracle_rz_um(0.12, 0.3, 2.0), 2.6248, wall_printed(1e-4));
  EXPECT_NEAR(oracle_rz_um(0.12, 0.3, 30.0), 6.0612, wall_printed(1e-4));
  EXPECT_NEAR(oracle_rz_um(10.0, 0.3, 2.0), 338.549, wall_printed(1e-3));
}

}  // namespace
