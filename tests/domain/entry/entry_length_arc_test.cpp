// Unit tests: entry length over convex and concave arcs (spec entry-and-main-time.md 6.3, 6.4, 11,
// 13). Expected values are the closed forms E17-E21 written out for the given inputs.

#include <gtest/gtest.h>

#include <cmath>

#include "domain/entry/closed_forms.h"
#include "domain/entry/entry_length.h"
#include "domain/entry/entry_test_support.h"

namespace {

namespace oracle = cutcalc::test::entry_oracle;
using cutcalc::domain::ErrorCode;
using cutcalc::domain::entry::compute_entry_length;
using cutcalc::domain::entry::EntryLengthResult;
using cutcalc::test::concave_contour;
using cutcalc::test::convex_contour;
using cutcalc::test::entry_exit;
using cutcalc::test::entry_only;
using cutcalc::test::outcome;
using cutcalc::test::straight_contour;

using cutcalc::test::kSpec2;
using cutcalc::test::kTol;

double root(double p, double q) { return std::sqrt((p - q) * (p + q)); }

// E18 full-width entry values for a convex arc.
struct Full {
  double engagement;
  double start_x;
};
Full case_a(double R, double r, double k, double approach = 2.0) {
  const double T = root(R + r, k);
  return {T - root(R, k + r), approach + T - R};
}
Full case_b(double R, double r, double k, double approach = 2.0) {
  const double T = root(R + r, k);
  return {T - root(r, k - R), approach + T - R};
}
Full case_c(double R, double r, double k, double approach = 2.0) {
  const double T = root(R + r, k);
  return {T - root(R, r - k), approach + T - R};
}
Full case_d(double R, double r, double k, double approach = 2.0) {
  const double T = root(R + r, k);
  return {T - root(r, R + k), approach + T - R};
}

EntryLengthResult convex_entry_ok(double D, double K, double R) {
  const auto res = compute_entry_length(entry_only(D, K, convex_contour(R)));
  EXPECT_TRUE(res.ok()) << outcome(res) << " (D=" << D << " K=" << K << " R=" << R << ")";
  return res.ok() ? res.value() : EntryLengthResult{};
}

}  // namespace

// ---- E18 full width, cases A-D
// ---------------------------------------------------------------------

TEST(EntryLengthConvexArc, CaseASmallCutterInsideTheArc) {
  // T2 row 3: D = 20, K = 15, R = 50, exit on the same arc, L = 200.
  const auto res = compute_entry_length(
      entry_exit(20.0, 15.0, convex_contour(50.0), convex_contour(50.0), 200.0));
  ASSERT_TRUE(res.ok()) << outcome(res);
  const auto& v = res.value();
  const Full want = case_a(50.0, 10.0, 15.0);
  EXPECT_NEAR(v.engagement_length_mm, want.engagement, kTol);
  EXPECT_NEAR(v.entry_length_mm, 2.0 + want.engagement, kTol);
  EXPECT_NEAR(v.start.x_mm, want.start_x, kTol);
  EXPECT_NEAR(v.start.y_mm, 15.0, kTol);  // arcs: Y_n = K
  EXPECT_NEAR(v.steady_width_mm, 20.0, kTol);
  ASSERT_TRUE(v.exit.has_value());
  const double end = 50.0 - root(50.0, 10.0 - 15.0);  // E19, k >= r - R
  EXPECT_NEAR(v.exit->end.x_mm, end, kTol);
  EXPECT_NEAR(v.exit->end.y_mm, 15.0, kTol);
  EXPECT_NEAR(v.exit->working_stroke_mm, 200.0 + want.start_x - end + 2.0, kTol);
}

TEST(EntryLengthConvexArc, CaseACentredCutterNearlyAsWideAsTheArc) {
  // T2 row 1: D = 48, R = 25, K = 0: T = 49, Q = 7 -> L_vr1 = 42, X_n = 26, X_k = 25 - 7 = 18.
  const auto res = compute_entry_length(
      entry_exit(48.0, 0.0, convex_contour(25.0), convex_contour(25.0), 150.0));
  ASSERT_TRUE(res.ok()) << outcome(res);
  EXPECT_NEAR(res.value().engagement_length_mm, 42.0, kTol);
  EXPECT_NEAR(res.value().start.x_mm, 26.0, kTol);
  EXPECT_NEAR(res.value().steady_width_mm, 48.0, kTol);
  ASSERT_TRUE(res.value().exit.has_value());
  EXPECT_NEAR(res.value().exit->end.x_mm, 18.0, kTol);
  EXPECT_NEAR(res.value().exit->working_stroke_mm, 150.0 + 26.0 - 18.0 + 2.0, kTol);
}

TEST(EntryLengthConvexArc, T2Row3WithNegativeOffsetUsesAbsoluteOffset) {
  // Printed second root sqrt(R^2 - (D/2 + K)^2) is wrong for K < 0; right: |K|.
  const auto v = convex_entry_ok(20.0, -15.0, 50.0);
  const Full want = case_a(50.0, 10.0, 15.0);
  EXPECT_NEAR(v.engagement_length_mm, want.engagement, kTol);
  EXPECT_NEAR(v.start.x_mm, want.start_x, kTol);
  EXPECT_NEAR(v.start.y_mm, -15.0, kTol);
  const double printed = root(60.0, 15.0) - root(50.0, 10.0 - 15.0);
  EXPECT_GT(std::abs(v.engagement_length_mm - printed), 1.0);
}

TEST(EntryLengthConvexArc, T2Row4ForCutterBetweenRAnd2RUsesCaseAOrB) {
  // Errata (H19): with R < D < 2R the printed Q = sqrt(R^2 - (D/2 - K)^2) is wrong.
  // R = 10, D = 15 (r = 7.5): K = 1 is case A (k + r <= R), K = 4 is case B (k + r > R).
  {
    const auto v = convex_entry_ok(15.0, 1.0, 10.0);
    const Full want = case_a(10.0, 7.5, 1.0);
    EXPECT_NEAR(v.engagement_length_mm, want.engagement, kTol);
    EXPECT_NEAR(v.start.x_mm, want.start_x, kTol);
    const double printed = root(17.5, 1.0) - root(10.0, 7.5 - 1.0);
    EXPECT_GT(std::abs(v.engagement_length_mm - printed), 1.0);
  }
  {
    const auto v = convex_entry_ok(15.0, 4.0, 10.0);
    const Full want = case_b(10.0, 7.5, 4.0);
    EXPECT_NEAR(v.engagement_length_mm, want.engagement, kTol);
    EXPECT_NEAR(v.start.x_mm, want.start_x, kTol);
    const double printed = root(17.5, 4.0) - root(10.0, 7.5 - 4.0);
    EXPECT_GT(std::abs(v.engagement_length_mm - printed), 1.0);
  }
}

TEST(EntryLengthConvexArc, CaseBOffsetBeyondTheArcAxisStartsDownstreamOfTheApex) {
  // T2 row 6 errata (H18): R = 20, D = 16, K = 24: X_n = L_pod + T - R = -3.58 (printed -7.58);
  // L_vr1 = T - sqrt(r^2 - (k - R)^2).
  const auto res = compute_entry_length(entry_only(16.0, 24.0, convex_contour(20.0)));
  ASSERT_TRUE(res.ok()) << outcome(res);
  const auto& v = res.value();
  const Full want = case_b(20.0, 8.0, 24.0);
  EXPECT_NEAR(v.start.x_mm, -3.58, kSpec2);
  EXPECT_NEAR(v.start.x_mm, want.start_x, kTol);
  EXPECT_NEAR(v.engagement_length_mm, want.engagement, kTol);
  EXPECT_NEAR(v.start.y_mm, 24.0, kTol);
  EXPECT_NEAR(v.steady_width_mm, 20.0 - 16.0, kTol);
  // K^2 > r^2 + 2 R r: first contact downstream of the apex, X_n < L_pod.
  EXPECT_LT(v.start.x_mm, 2.0);
  const double printed_q = root(20.0, 24.0 - 8.0);
  EXPECT_GT(std::abs(v.engagement_length_mm - (root(28.0, 24.0) - printed_q)), 1.0);
}

TEST(EntryLengthConvexArc, CaseBOffsetWithinTheArcAxis) {
  // Missing from the paper (H17): r <= R < k + r with k <= R. R = 20, D = 16, K = 15.
  const auto v = convex_entry_ok(16.0, 15.0, 20.0);
  const Full want = case_b(20.0, 8.0, 15.0);
  EXPECT_NEAR(v.engagement_length_mm, want.engagement, kTol);
  EXPECT_NEAR(v.start.x_mm, want.start_x, kTol);
  EXPECT_NEAR(v.steady_width_mm, 20.0 - 7.0, kTol);
}

TEST(EntryLengthConvexArc, CaseCCutterWiderThanTheArc) {
  // T2 row 4 in its valid domain D >= 2R: D = 30, K = 8, R = 10 (r = 15 <= R + k = 18).
  const auto res = compute_entry_length(
      entry_exit(30.0, 8.0, convex_contour(10.0), convex_contour(10.0), 100.0));
  ASSERT_TRUE(res.ok()) << outcome(res);
  const auto& v = res.value();
  const Full want = case_c(10.0, 15.0, 8.0);
  EXPECT_NEAR(v.engagement_length_mm, want.engagement, kTol);
  EXPECT_NEAR(v.start.x_mm, want.start_x, kTol);
  EXPECT_NEAR(v.steady_width_mm, 10.0 - (-7.0), kTol);
  ASSERT_TRUE(v.exit.has_value());
  // E19: k = 8 >= r - R = 5 -> X_k = R - sqrt(R^2 - (r - k)^2).
  const double end = 10.0 - root(10.0, 15.0 - 8.0);
  EXPECT_NEAR(v.exit->end.x_mm, end, kTol);
  EXPECT_NEAR(v.exit->working_stroke_mm, 100.0 + want.start_x - end + 2.0, kTol);
}

TEST(EntryLengthConvexArc, T2Row7WithinItsRangeIsCaseC) {
  // D = 30, K = 12, R = 5: r = 15 <= R + K = 17: T = 16, Q = 4 -> L_vr1 = 12, X_n = 13.
  const auto v = convex_entry_ok(30.0, 12.0, 5.0);
  EXPECT_NEAR(v.engagement_length_mm, 12.0, kTol);
  EXPECT_NEAR(v.start.x_mm, 13.0, kTol);
  EXPECT_NEAR(v.steady_width_mm, 8.0, kTol);
}

TEST(EntryLengthConvexArc, T2Row7BeyondItsRangeIsCaseD) {
  // D = 40, K = 12, R = 5: r = 20 > R + K = 17, the printed row-7 root is imaginary; case D.
  const auto v = convex_entry_ok(40.0, 12.0, 5.0);
  const Full want = case_d(5.0, 20.0, 12.0);
  EXPECT_NEAR(v.engagement_length_mm, want.engagement, kTol);
  EXPECT_NEAR(v.start.x_mm, want.start_x, kTol);
  EXPECT_TRUE(std::isfinite(v.engagement_length_mm));
}

TEST(EntryLengthConvexArc, CaseDCentredCutterEngulfsTheArc) {
  // T2 row 2 (K = 0): L_vr1 = r + R - sqrt(r^2 - R^2); D = 30, R = 10: X_n = 17, X_k = R + (r - R).
  const auto res = compute_entry_length(
      entry_exit(30.0, 0.0, convex_contour(10.0), convex_contour(10.0), 100.0));
  ASSERT_TRUE(res.ok()) << outcome(res);
  const auto& v = res.value();
  EXPECT_NEAR(v.engagement_length_mm, 15.0 + 10.0 - root(15.0, 10.0), kTol);
  EXPECT_NEAR(v.start.x_mm, 17.0, kTol);
  EXPECT_NEAR(v.steady_width_mm, 20.0, kTol);
  ASSERT_TRUE(v.exit.has_value());
  EXPECT_NEAR(v.exit->end.x_mm, 15.0, kTol);
  EXPECT_NEAR(v.exit->working_stroke_mm, 100.0 + 17.0 - 15.0 + 2.0, kTol);
}

TEST(EntryLengthConvexArc, T2Row5CorrectedIsCaseDForEitherSign) {
  // Right: Q = sqrt(r^2 - (R + |K|)^2), r >= R + |K|. D = 40, R = 10, K = +-5.
  for (double K : {5.0, -5.0}) {
    const auto v = convex_entry_ok(40.0, K, 10.0);
    const Full want = case_d(10.0, 20.0, 5.0);
    EXPECT_NEAR(v.engagement_length_mm, want.engagement, kTol) << "K = " << K;
    EXPECT_NEAR(v.start.x_mm, want.start_x, kTol) << "K = " << K;
    EXPECT_NEAR(v.start.y_mm, K, kTol);
  }
}

TEST(EntryLengthConvexArc, CasesJoinContinuously) {
  // Each join evaluated exactly on it (both neighbouring formulas agree there) and just either side
  // (each side follows its own formula, and the values close in on the join value).
  struct Join {
    const char* name;
    double R, r, k;  // a point exactly on the join
    Full (*below)(double, double, double, double);
    Full (*above)(double, double, double, double);
    bool vary_k;  // the join is crossed by moving k (else by moving r)
  };
  const Join joins[] = {
      {"A/B: k + r = R", 20.0, 8.0, 12.0, case_a, case_b, true},
      {"B/C: r = R", 10.0, 10.0, 4.0, case_b, case_c, false},
      {"C/D: r = R + k", 10.0, 15.0, 5.0, case_c, case_d, true},
  };
  for (const Join& j : joins) {
    const Full lo = j.below(j.R, j.r, j.k, 2.0);
    const Full hi = j.above(j.R, j.r, j.k, 2.0);
    EXPECT_NEAR(lo.engagement, hi.engagement, kTol) << j.name;
    const auto on = convex_entry_ok(2.0 * j.r, j.k, j.R);
    EXPECT_NEAR(on.engagement_length_mm, lo.engagement, kTol) << j.name;
    EXPECT_NEAR(on.start.x_mm, lo.start_x, kTol) << j.name;
    double previous_gap = 1e300;
    for (double delta : {1e-2, 1e-4, 1e-6, 1e-8}) {
      // A/B: k below the join is A; C/D: k above the join is C (r >= R + k is D).
      for (int side : {-1, +1}) {
        const double k = j.vary_k ? j.k + side * delta : j.k;
        const double r = j.vary_k ? j.r : j.r + side * delta;
        const bool first_case = (j.name[0] == 'C') ? side > 0 : side < 0;
        const Full want = first_case ? j.below(j.R, r, k, 2.0) : j.above(j.R, r, k, 2.0);
        const auto got = convex_entry_ok(2.0 * r, k, j.R);
        EXPECT_NEAR(got.engagement_length_mm, want.engagement, kTol)
            << j.name << " delta " << side * delta;
        const double gap = std::abs(got.engagement_length_mm - on.engagement_length_mm);
        EXPECT_LT(gap, 10.0 * std::sqrt(delta * (j.R + j.r))) << j.name << " delta " << delta;
        if (side > 0) {
          EXPECT_LE(gap, previous_gap) << j.name;
          previous_gap = gap;
        }
      }
    }
  }
}

TEST(EntryLengthConvexArc, SymmetricInOffset) {
  for (double R : {5.0, 20.0, 50.0}) {
    for (double D : {6.0, 16.0, 40.0, 90.0}) {
      for (double K : {0.75, 4.0, 11.0, 24.0, 40.0}) {
        const auto plus =
            compute_entry_length(entry_exit(D, K, convex_contour(R), convex_contour(R), 500.0));
        const auto minus =
            compute_entry_length(entry_exit(D, -K, convex_contour(R), convex_contour(R), 500.0));
        ASSERT_EQ(plus.ok(), minus.ok()) << "R=" << R << " D=" << D << " K=" << K;
        if (!plus.ok()) {
          EXPECT_EQ(plus.error().code, ErrorCode::no_contact);
          EXPECT_EQ(minus.error().code, ErrorCode::no_contact);
          continue;
        }
        EXPECT_NEAR(plus.value().engagement_length_mm, minus.value().engagement_length_mm, kTol);
        EXPECT_NEAR(plus.value().start.x_mm, minus.value().start.x_mm, kTol);
        EXPECT_NEAR(plus.value().steady_width_mm, minus.value().steady_width_mm, kTol);
        EXPECT_NEAR(plus.value().start.y_mm, K, kTol);
        EXPECT_NEAR(minus.value().start.y_mm, -K, kTol);
        ASSERT_TRUE(plus.value().exit && minus.value().exit);
        EXPECT_NEAR(plus.value().exit->end.x_mm, minus.value().exit->end.x_mm, kTol);
        EXPECT_NEAR(minus.value().exit->end.y_mm, -K, kTol);
      }
    }
  }
}

TEST(EntryLengthConvexArc, LargeRadiusTendsToTheStraightEdge) {
  // Section 11 (H15): R = 1e5, r = 10 -> L_vr1 -> r (straight S1), X_n -> L_pod + r, X_k -> 0.
  const auto res =
      compute_entry_length(entry_exit(20.0, 0.0, convex_contour(1e5), convex_contour(1e5), 100.0));
  ASSERT_TRUE(res.ok()) << outcome(res);
  const auto& v = res.value();
  EXPECT_NEAR(v.engagement_length_mm, 10.0, 1e-3);
  EXPECT_NEAR(v.start.x_mm, 12.0, 1e-9);  // T - R = r exactly for K = 0
  ASSERT_TRUE(v.exit.has_value());
  EXPECT_NEAR(v.exit->end.x_mm, 0.0, 1e-3);
  const Full want = case_a(1e5, 10.0, 0.0);
  EXPECT_NEAR(v.engagement_length_mm, want.engagement, kTol);
  // Off centre too: the limit is S1 for any band inside the strip.
  const auto off = convex_entry_ok(20.0, 30.0, 1e5);
  EXPECT_NEAR(off.engagement_length_mm, 10.0, 5e-3);
  EXPECT_NEAR(off.engagement_length_mm, case_a(1e5, 10.0, 30.0).engagement, kTol);
}

TEST(EntryLengthConvexArc, TangentOffsetIsNoContact) {
  for (double K : {28.0, -28.0, 40.0}) {  // |K| = R + r = 28 and beyond
    const auto res = compute_entry_length(entry_only(16.0, K, convex_contour(20.0)));
    ASSERT_FALSE(res.ok()) << "K = " << K;
    EXPECT_EQ(res.error().code, ErrorCode::no_contact);
  }
}

TEST(EntryLengthConvexArc, PartialWidthClipsTheBandToTheWidth) {
  // H31: R = 50, width 60 (h = 30), D = 20, K = 25: band [15, 30], W = 15; E17 with h = B/2.
  const auto res = compute_entry_length(
      entry_exit(20.0, 25.0, convex_contour(50.0, 60.0), convex_contour(50.0, 60.0), 200.0));
  ASSERT_TRUE(res.ok()) << outcome(res);
  const auto& v = res.value();
  const auto e = oracle::convex_entry(20.0, 50.0, 60.0, 25.0, 2.0);
  const auto x = oracle::convex_exit(20.0, 50.0, 60.0, 25.0);
  ASSERT_TRUE(e && x);
  EXPECT_NEAR(v.steady_width_mm, 15.0, kTol);
  EXPECT_NEAR(v.engagement_length_mm, e->engagement_mm, kTol);
  EXPECT_NEAR(v.start.x_mm, e->start_x_mm, kTol);
  EXPECT_NEAR(v.start.y_mm, 25.0, kTol);
  ASSERT_TRUE(v.exit.has_value());
  EXPECT_NEAR(v.exit->end.x_mm, x->end_x_mm, kTol);
  // Written out: saturation at the larger of psi(a = 15) = R - sqrt(R^2 - 15^2) (s = 0) and
  // psi(b = h = 30) = R - sqrt(R^2 - h^2) - s(h - K); here psi(a) = 2.30 > psi(b) = 1.34. First
  // contact at the free minimum y* = K R / (R + r) = 20.8, inside the band:
  // x_c0 = R - sqrt((R + r)^2 - K^2).
  const double psi_a = 50.0 - root(50.0, 15.0);
  const double psi_b = 50.0 - root(50.0, 30.0) - root(10.0, 5.0);
  ASSERT_GT(psi_a, psi_b);
  const double xcs = psi_a;
  const double xc0 = 50.0 - root(60.0, 25.0);
  EXPECT_NEAR(v.engagement_length_mm, xcs - xc0, kTol);
  EXPECT_NEAR(v.start.x_mm, 2.0 - xc0, kTol);
  // The stop: phi max over {a = 15, b = 30}; phi(15) = sqrt(R^2 - 15^2) - R (s = 0).
  const double phi_a = root(50.0, 15.0) - 50.0;
  const double phi_b = root(50.0, 30.0) - 50.0 - root(10.0, 5.0);
  EXPECT_NEAR(v.exit->end.x_mm, -std::max(phi_a, phi_b), kTol);
}

TEST(EntryLengthConvexArc, PartialWidthWithTheBandInsideEqualsFullWidth) {
  // When the band does not reach +-h the width does not matter.
  const auto partial = compute_entry_length(entry_only(20.0, 5.0, convex_contour(50.0, 60.0)));
  const auto full = compute_entry_length(entry_only(20.0, 5.0, convex_contour(50.0)));
  ASSERT_TRUE(partial.ok() && full.ok());
  EXPECT_NEAR(partial.value().engagement_length_mm, full.value().engagement_length_mm, kTol);
  EXPECT_NEAR(partial.value().start.x_mm, full.value().start.x_mm, kTol);
  // An explicit width_mm = 2R is the full arc.
  const auto explicit_full =
      compute_entry_length(entry_only(90.0, 12.0, convex_contour(20.0, 40.0)));
  const auto implicit_full = compute_entry_length(entry_only(90.0, 12.0, convex_contour(20.0)));
  ASSERT_TRUE(explicit_full.ok() && implicit_full.ok());
  EXPECT_NEAR(explicit_full.value().engagement_length_mm,
              implicit_full.value().engagement_length_mm, kTol);
  EXPECT_NEAR(explicit_full.value().start.x_mm, implicit_full.value().start.x_mm, kTol);
}

TEST(EntryLengthConvexArc, ExitWhenTheCutterEngulfsTheArc) {
  // E19 full width, k < r - R: X_k = R + sqrt((r - R)^2 - K^2). D = 30, R = 10, K = 3 -> 14.
  const auto res = compute_entry_length(
      entry_exit(30.0, 3.0, convex_contour(10.0), convex_contour(10.0), 100.0));
  ASSERT_TRUE(res.ok()) << outcome(res);
  ASSERT_TRUE(res.value().exit.has_value());
  EXPECT_NEAR(res.value().exit->end.x_mm, 14.0, kTol);
  EXPECT_NEAR(res.value().exit->end.y_mm, 3.0, kTol);
}

TEST(EntryLengthConvexArc, ExitOfASmallCutter) {
  // E19 otherwise: X_k = R - sqrt(R^2 - (r - k)^2). D = 20, R = 30, K = 0 -> 30 - sqrt(800).
  const auto res = compute_entry_length(
      entry_exit(20.0, 0.0, convex_contour(30.0), convex_contour(30.0), 150.0));
  ASSERT_TRUE(res.ok()) << outcome(res);
  ASSERT_TRUE(res.value().exit.has_value());
  EXPECT_NEAR(res.value().exit->end.x_mm, 30.0 - std::sqrt(800.0), kTol);
  EXPECT_NEAR(res.value().exit->working_stroke_mm, 150.0 + 12.0 - (30.0 - std::sqrt(800.0)) + 2.0,
              kTol);
}

TEST(EntryLengthConvexArc, MixedStraightEntryAndConvexExitShareTheAxis) {
  // Straight entry B = 60 (Y from the side edge) and a convex exit R = 30 (Y from the arc axis).
  const auto res = compute_entry_length(
      entry_exit(20.0, 6.0, straight_contour(60.0), convex_contour(30.0), 150.0));
  ASSERT_TRUE(res.ok()) << outcome(res);
  EXPECT_NEAR(res.value().start.y_mm, 36.0, kTol);
  ASSERT_TRUE(res.value().exit.has_value());
  EXPECT_NEAR(res.value().exit->end.y_mm, 6.0, kTol);
  EXPECT_NEAR(res.value().exit->end.x_mm, 30.0 - root(30.0, 10.0 - 6.0), kTol);
}

// ---- concave arc (E20-E21) ---------------------------------------------------------------------

TEST(EntryLengthConcaveArc, SmallCutterFirstTouchesInsideTheNotch) {
  // R = 50, B = 60 (c0 = 40), D = 10, K = 0: psi(0) = R - c0 - r = 5 (y_c = 0) is the minimum,
  // psi(+-r) = sqrt(R^2 - r^2) - c0 the maximum.
  const auto res = compute_entry_length(entry_only(10.0, 0.0, concave_contour(50.0, 60.0)));
  ASSERT_TRUE(res.ok()) << outcome(res);
  const auto& v = res.value();
  EXPECT_NEAR(v.engagement_length_mm, (root(50.0, 5.0) - 40.0) - 5.0, kTol);
  EXPECT_NEAR(v.start.x_mm, 2.0 - 5.0, kTol);
  EXPECT_NEAR(v.start.y_mm, 0.0, kTol);
  EXPECT_NEAR(v.steady_width_mm, 10.0, kTol);
}

TEST(EntryLengthConcaveArc, InteriorMaximumWhenTheCutterRadiusExceedsTheArcRadius) {
  // HX02: R = 10, B = 16 (h = 8, c0 = 6), D = 30 (r = 15), K = 2. y_c = R K / (R - r) = -4 is
  // inside the band [-8, 8] and psi(y_c) = sqrt(84) - 6 - sqrt(189) beats both ends
  // (psi(-8) = -sqrt(125), psi(8) = -sqrt(189)): L_vr1 = sqrt(84) - 6, not the ends-only 2.57.
  const auto res = compute_entry_length(entry_only(30.0, 2.0, concave_contour(10.0, 16.0)));
  ASSERT_TRUE(res.ok()) << outcome(res);
  const auto& v = res.value();
  const double psi_c = std::sqrt(84.0) - 6.0 - std::sqrt(189.0);
  const double psi_min = -std::sqrt(189.0);
  EXPECT_NEAR(v.engagement_length_mm, psi_c - psi_min, kTol);
  EXPECT_NEAR(v.start.x_mm, 2.0 - psi_min, kTol);
  EXPECT_NEAR(v.steady_width_mm, 16.0, kTol);
  const double ends_only = -std::sqrt(125.0) - psi_min;
  EXPECT_GT(v.engagement_length_mm - ends_only, 0.5);
  EXPECT_TRUE(oracle::concave_entry_max_is_interior(30.0, 10.0, 16.0, 2.0));
}

TEST(EntryLengthConcaveArc, ExitMaximumIsAtABandEnd) {
  // E21 for the HX02 geometry: phi(-8) = -sqrt(125), phi(8) = -sqrt(189) -> X_k = sqrt(125).
  const auto res = compute_entry_length(
      entry_exit(30.0, 2.0, concave_contour(10.0, 16.0), concave_contour(10.0, 16.0), 100.0));
  ASSERT_TRUE(res.ok()) << outcome(res);
  ASSERT_TRUE(res.value().exit.has_value());
  EXPECT_NEAR(res.value().exit->end.x_mm, std::sqrt(125.0), kTol);
  EXPECT_NEAR(res.value().exit->end.y_mm, 2.0, kTol);
  EXPECT_NEAR(res.value().exit->working_stroke_mm,
              100.0 + (2.0 + std::sqrt(189.0)) - std::sqrt(125.0) + 2.0, kTol);
}

TEST(EntryLengthConcaveArc, SemicircularNotch) {
  // R = h: c0 = 0. B = 40, R = 20, D = 10, K = 0: psi(0) = 20 - 5 = 15, psi(+-5) = sqrt(375).
  const auto res = compute_entry_length(
      entry_exit(10.0, 0.0, concave_contour(20.0, 40.0), concave_contour(20.0, 40.0), 100.0));
  ASSERT_TRUE(res.ok()) << outcome(res);
  const auto& v = res.value();
  EXPECT_NEAR(v.engagement_length_mm, std::sqrt(375.0) - 15.0, kTol);
  EXPECT_NEAR(v.start.x_mm, 2.0 - 15.0, kTol);
  ASSERT_TRUE(v.exit.has_value());
  // phi(+-5) = 0 - sqrt(375) - 0 -> X_k = sqrt(375).
  EXPECT_NEAR(v.exit->end.x_mm, std::sqrt(375.0), kTol);
}

TEST(EntryLengthConcaveArc, MatchesClosedFormsOnAGrid) {
  for (double R : {10.0, 12.0, 30.0}) {
    for (double D : {4.0, 15.0, 26.0, 60.0}) {
      for (double K : {-12.0, -5.0, 0.0, 3.0, 9.5}) {
        const double B = 20.0;
        const auto res = compute_entry_length(
            entry_exit(D, K, concave_contour(R, B), concave_contour(R, B), 400.0));
        const auto e = oracle::concave_entry(D, R, B, K, 2.0);
        const auto x = oracle::concave_exit(D, R, B, K);
        if (!e) {
          ASSERT_FALSE(res.ok());
          EXPECT_EQ(res.error().code, ErrorCode::no_contact);
          continue;
        }
        ASSERT_TRUE(res.ok()) << outcome(res) << " R=" << R << " D=" << D << " K=" << K;
        ASSERT_TRUE(x.has_value());
        const auto& v = res.value();
        EXPECT_NEAR(v.engagement_length_mm, e->engagement_mm, kTol)
            << "R=" << R << " D=" << D << " K=" << K;
        EXPECT_NEAR(v.start.x_mm, e->start_x_mm, kTol) << "R=" << R << " D=" << D << " K=" << K;
        EXPECT_NEAR(v.start.y_mm, K, kTol);
        ASSERT_TRUE(v.exit.has_value());
        EXPECT_NEAR(v.exit->end.x_mm, x->end_x_mm, kTol) << "R=" << R << " D=" << D << " K=" << K;
      }
    }
  }
}

TEST(EntryLengthConcaveArc, SymmetricInOffset) {
  for (double D : {4.0, 15.0, 26.0, 60.0}) {
    for (double K : {1.0, 5.0, 9.0, 14.0}) {
      const auto plus = compute_entry_length(
          entry_exit(D, K, concave_contour(12.0, 20.0), concave_contour(12.0, 20.0), 400.0));
      const auto minus = compute_entry_length(
          entry_exit(D, -K, concave_contour(12.0, 20.0), concave_contour(12.0, 20.0), 400.0));
      ASSERT_EQ(plus.ok(), minus.ok());
      if (!plus.ok()) {
        continue;
      }
      EXPECT_NEAR(plus.value().engagement_length_mm, minus.value().engagement_length_mm, kTol);
      EXPECT_NEAR(plus.value().start.x_mm, minus.value().start.x_mm, kTol);
      ASSERT_TRUE(plus.value().exit && minus.value().exit);
      EXPECT_NEAR(plus.value().exit->end.x_mm, minus.value().exit->end.x_mm, kTol);
    }
  }
}

TEST(EntryLengthConcaveArc, TangentOffsetIsNoContact) {
  const auto res = compute_entry_length(entry_only(10.0, -15.0, concave_contour(12.0, 20.0)));
  ASSERT_FALSE(res.ok());
  EXPECT_EQ(res.error().code, ErrorCode::no_contact);
}
