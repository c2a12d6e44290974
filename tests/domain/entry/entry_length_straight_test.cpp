// Unit tests: entry length over straight edges (spec entry-and-main-time.md 6.1, 6.2, 11, 13).
// Expected values are the spec's closed forms written out for the given inputs, or the numbers the
// spec states itself (sections 3, 11, 13).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "domain/common/numeric.h"
#include "domain/entry/closed_forms.h"
#include "domain/entry/entry_length.h"
#include "domain/entry/entry_test_support.h"

namespace {

namespace oracle = cutcalc::test::entry_oracle;
using cutcalc::domain::ErrorCode;
using cutcalc::domain::entry::compute_entry_length;
using cutcalc::test::entry_exit;
using cutcalc::test::entry_only;
using cutcalc::test::outcome;
using cutcalc::test::straight_contour;

using cutcalc::test::kTol;
constexpr double kSpec3 = 5e-4;  // numbers the spec prints with 3 decimals
using cutcalc::test::kSpec2;

double deg(double d) { return cutcalc::domain::deg_to_rad(d); }

}  // namespace

// ---- 6.1: alpha = 90, sub-cases S1-S4 (E13)
// -------------------------------------------------------

TEST(EntryLengthStraight, FullBandInsideStripEntersOverOneRadius) {
  // S1: D = 20, B = 60, K = 0 -> L_vr1 = r, X_n = L_pod + r, perpendicular exit X_k = 0.
  const auto res = compute_entry_length(
      entry_exit(20.0, 0.0, straight_contour(60.0), straight_contour(60.0), 100.0));
  ASSERT_TRUE(res.ok()) << outcome(res);
  const auto& v = res.value();
  EXPECT_NEAR(v.engagement_length_mm, 10.0, kTol);
  EXPECT_NEAR(v.entry_length_mm, 12.0, kTol);
  EXPECT_NEAR(v.start.x_mm, 12.0, kTol);
  EXPECT_NEAR(v.start.y_mm, 30.0, kTol);  // Y_n = h + K
  EXPECT_NEAR(v.steady_width_mm, 20.0, kTol);
  ASSERT_TRUE(v.exit.has_value());
  EXPECT_NEAR(v.exit->end.x_mm, 0.0, kTol);
  EXPECT_NEAR(v.exit->end.y_mm, 30.0, kTol);
  EXPECT_NEAR(v.exit->working_stroke_mm, 100.0 + 12.0 - 0.0 + 2.0, kTol);  // E9
}

TEST(EntryLengthStraight, CutterOverhangingSideEdgeStillEntersOverOneRadius) {
  // S1 (T1 row 4): D = 30, B = 40, K = 10: k <= h and r <= h + k; the band is clipped at y = h.
  const auto res = compute_entry_length(
      entry_exit(30.0, 10.0, straight_contour(40.0), straight_contour(40.0), 100.0));
  ASSERT_TRUE(res.ok()) << outcome(res);
  const auto& v = res.value();
  EXPECT_NEAR(v.engagement_length_mm, 15.0, kTol);
  EXPECT_NEAR(v.entry_length_mm, 17.0, kTol);
  EXPECT_NEAR(v.start.x_mm, 17.0, kTol);
  EXPECT_NEAR(v.start.y_mm, 30.0, kTol);
  EXPECT_NEAR(v.steady_width_mm, 20.0 - (-5.0), kTol);  // [max(K - r, -h), min(K + r, h)]
  ASSERT_TRUE(v.exit.has_value());
  EXPECT_NEAR(v.exit->end.x_mm, 0.0, kTol);
  EXPECT_NEAR(v.exit->working_stroke_mm, 119.0, kTol);
}

TEST(EntryLengthStraight, CutterWiderThanStripSaturatesBeforeOneRadius) {
  // S2 (T1 row 2): D = 50, B = 25, K = 0: L_vr1 = r - sqrt(r^2 - (h + k)^2), X_k = sqrt(r^2 -
  // (h+k)^2).
  const double r = 25.0;
  const double q = std::sqrt(r * r - 12.5 * 12.5);
  const auto res = compute_entry_length(
      entry_exit(50.0, 0.0, straight_contour(25.0), straight_contour(25.0), 80.0));
  ASSERT_TRUE(res.ok()) << outcome(res);
  const auto& v = res.value();
  EXPECT_NEAR(v.engagement_length_mm, r - q, kTol);
  EXPECT_NEAR(v.entry_length_mm, 2.0 + r - q, kTol);
  EXPECT_NEAR(v.start.x_mm, 2.0 + r, kTol);
  EXPECT_NEAR(v.start.y_mm, 12.5, kTol);
  EXPECT_NEAR(v.steady_width_mm, 25.0, kTol);
  ASSERT_TRUE(v.exit.has_value());
  EXPECT_NEAR(v.exit->end.x_mm, q, kTol);
  EXPECT_NEAR(v.exit->working_stroke_mm, 80.0 + (2.0 + r) - q + 2.0, kTol);
}

TEST(EntryLengthStraight, OffsetCutterWiderThanStripUsesHalfWidthPlusOffset) {
  // S2 (T1 row 5): D = 36, B = 20, K = 4: h + k = 14 < r = 18.
  const double q = std::sqrt(18.0 * 18.0 - 14.0 * 14.0);
  const auto res = compute_entry_length(
      entry_exit(36.0, 4.0, straight_contour(20.0), straight_contour(20.0), 60.0));
  ASSERT_TRUE(res.ok()) << outcome(res);
  const auto& v = res.value();
  EXPECT_NEAR(v.engagement_length_mm, 18.0 - q, kTol);
  EXPECT_NEAR(v.start.x_mm, 20.0, kTol);
  EXPECT_NEAR(v.start.y_mm, 14.0, kTol);
  EXPECT_NEAR(v.steady_width_mm, 20.0, kTol);
  ASSERT_TRUE(v.exit.has_value());
  EXPECT_NEAR(v.exit->end.x_mm, q, kTol);
  EXPECT_NEAR(v.exit->end.y_mm, 14.0, kTol);
  EXPECT_NEAR(v.exit->working_stroke_mm, 60.0 + 20.0 - q + 2.0, kTol);
}

TEST(EntryLengthStraight, AxisOutsideStripEntersOverTheChordAtTheSideEdge) {
  // S3 (T1 row 6): D = 30, B = 40, K = 25: L_vr1 = X_n - L_pod = sqrt(r^2 - (k - h)^2), X_k = 0.
  const double c = std::sqrt(15.0 * 15.0 - 5.0 * 5.0);
  const auto res = compute_entry_length(
      entry_exit(30.0, 25.0, straight_contour(40.0), straight_contour(40.0), 100.0));
  ASSERT_TRUE(res.ok()) << outcome(res);
  const auto& v = res.value();
  EXPECT_NEAR(v.engagement_length_mm, c, kTol);
  EXPECT_NEAR(v.start.x_mm, 2.0 + c, kTol);
  EXPECT_NEAR(v.start.y_mm, 45.0, kTol);
  EXPECT_NEAR(v.steady_width_mm, 10.0, kTol);
  ASSERT_TRUE(v.exit.has_value());
  EXPECT_NEAR(v.exit->end.x_mm, 0.0, kTol);
  EXPECT_NEAR(v.exit->working_stroke_mm, 100.0 + 2.0 + c + 2.0, kTol);

  // D < B/2 (T1 row 6, second reading): D = 40, B = 100, K = 60.
  const auto res2 = compute_entry_length(entry_only(40.0, 60.0, straight_contour(100.0)));
  ASSERT_TRUE(res2.ok()) << outcome(res2);
  EXPECT_NEAR(res2.value().engagement_length_mm, std::sqrt(400.0 - 100.0), kTol);
  EXPECT_NEAR(res2.value().start.y_mm, 110.0, kTol);
  EXPECT_NEAR(res2.value().steady_width_mm, 10.0, kTol);
  EXPECT_FALSE(res2.value().exit.has_value());
}

TEST(EntryLengthStraight, AxisOutsideStripWithCutterCoveringTheStrip) {
  // S4 (missing from the paper, H08): B = 20, K = 12, D = 60: h < k and r > h + k.
  const double first = std::sqrt(30.0 * 30.0 - 2.0 * 2.0);   // sqrt(r^2 - (k - h)^2)
  const double last = std::sqrt(30.0 * 30.0 - 22.0 * 22.0);  // sqrt(r^2 - (h + k)^2)
  for (double K : {12.0, -12.0}) {
    const auto res = compute_entry_length(
        entry_exit(60.0, K, straight_contour(20.0), straight_contour(20.0), 100.0));
    ASSERT_TRUE(res.ok()) << outcome(res);
    const auto& v = res.value();
    EXPECT_NEAR(v.engagement_length_mm, first - last, kTol) << "K = " << K;
    EXPECT_NEAR(v.start.x_mm, 2.0 + first, kTol) << "K = " << K;
    EXPECT_NEAR(v.start.y_mm, 10.0 + K, kTol) << "K = " << K;
    EXPECT_NEAR(v.steady_width_mm, 20.0, kTol) << "K = " << K;
    ASSERT_TRUE(v.exit.has_value());
    EXPECT_NEAR(v.exit->end.x_mm, last, kTol) << "K = " << K;
    EXPECT_NEAR(v.exit->end.y_mm, 10.0 + K, kTol) << "K = " << K;
  }
}

TEST(EntryLengthStraight, CutterDiameterEqualToStripWidthIsS1) {
  // D = B (H04, matched by no printed row): r = h + k, L_vr1 = r, X_k = 0.
  const auto res = compute_entry_length(
      entry_exit(40.0, 0.0, straight_contour(40.0), straight_contour(40.0), 100.0));
  ASSERT_TRUE(res.ok()) << outcome(res);
  EXPECT_NEAR(res.value().engagement_length_mm, 20.0, kTol);
  EXPECT_NEAR(res.value().start.x_mm, 22.0, kTol);
  EXPECT_NEAR(res.value().steady_width_mm, 40.0, kTol);
  ASSERT_TRUE(res.value().exit.has_value());
  EXPECT_NEAR(res.value().exit->end.x_mm, 0.0, kTol);
}

TEST(EntryLengthStraight, RadiusEqualToHalfWidthPlusOffsetJoinsS1AndS2) {
  // r = B/2 + |K| (H06): D = 50, B = 40, K = 5. S1 gives r; S2 gives r - sqrt(r^2 - (h + k)^2) = r.
  for (double K : {5.0, -5.0}) {
    const auto res = compute_entry_length(
        entry_exit(50.0, K, straight_contour(40.0), straight_contour(40.0), 100.0));
    ASSERT_TRUE(res.ok()) << outcome(res);
    EXPECT_NEAR(res.value().engagement_length_mm, 25.0, kTol);
    EXPECT_NEAR(res.value().start.x_mm, 27.0, kTol);
    ASSERT_TRUE(res.value().exit.has_value());
    EXPECT_NEAR(res.value().exit->end.x_mm, 0.0, kTol);
  }
  // Just inside S2 the value follows S2's formula.
  const double K = 5.0 - 1.0 / 1024.0;
  const auto res = compute_entry_length(entry_only(50.0, K, straight_contour(40.0)));
  ASSERT_TRUE(res.ok()) << outcome(res);
  const double hk = 20.0 + K;
  EXPECT_NEAR(res.value().engagement_length_mm, 25.0 - std::sqrt(625.0 - hk * hk), kTol);
}

TEST(EntryLengthStraight, SmallCutterWithSmallOrNegativeOffsetIsS1) {
  // Errata T1 coverage: D = 20, B = 100 with K = 5 or K = -30 matches no printed row; S1 applies.
  for (double K : {5.0, -30.0}) {
    const auto res = compute_entry_length(entry_only(20.0, K, straight_contour(100.0)));
    ASSERT_TRUE(res.ok()) << outcome(res);
    EXPECT_NEAR(res.value().engagement_length_mm, 10.0, kTol) << "K = " << K;
    EXPECT_NEAR(res.value().start.x_mm, 12.0, kTol) << "K = " << K;
    EXPECT_NEAR(res.value().start.y_mm, 50.0 + K, kTol) << "K = " << K;
    EXPECT_NEAR(res.value().steady_width_mm, 20.0, kTol) << "K = " << K;
  }
}

TEST(EntryLengthStraight, T1Row4HoldsForNegativeOffsetWithinHalfWidth) {
  // D = 30, B = 40, K = -10: the mirror of the row-4 case; only Y carries the sign.
  const auto res = compute_entry_length(
      entry_exit(30.0, -10.0, straight_contour(40.0), straight_contour(40.0), 100.0));
  ASSERT_TRUE(res.ok()) << outcome(res);
  EXPECT_NEAR(res.value().engagement_length_mm, 15.0, kTol);
  EXPECT_NEAR(res.value().start.x_mm, 17.0, kTol);
  EXPECT_NEAR(res.value().start.y_mm, 10.0, kTol);
  EXPECT_NEAR(res.value().steady_width_mm, 25.0, kTol);
  ASSERT_TRUE(res.value().exit.has_value());
  EXPECT_NEAR(res.value().exit->end.y_mm, 10.0, kTol);
  EXPECT_NEAR(res.value().exit->working_stroke_mm, 119.0, kTol);
}

TEST(EntryLengthStraight, T1Row4MisprintedConditionNegativeOffsetBeyondHalfWidthIsS3) {
  // The printed condition K <= B/2 admits K = -25 (B = 40, D = 30) and would give L_vr1 = r = 15;
  // the axis is outside the strip, so S3: sqrt(r^2 - (k - h)^2).
  const auto res = compute_entry_length(entry_only(30.0, -25.0, straight_contour(40.0)));
  ASSERT_TRUE(res.ok()) << outcome(res);
  const double right = std::sqrt(225.0 - 25.0);
  EXPECT_NEAR(res.value().engagement_length_mm, right, kTol);
  EXPECT_GT(std::abs(res.value().engagement_length_mm - 15.0), 0.5);
  EXPECT_NEAR(res.value().start.y_mm, -5.0, kTol);
}

TEST(EntryLengthStraight, T1Row5WithNegativeOffsetUsesAbsoluteOffset) {
  // Printed: L_vr1 = r - sqrt(r^2 - (B/2 + K)^2); right: |K|. D = 36, B = 20, K = -4.
  const double right = 18.0 - std::sqrt(324.0 - 14.0 * 14.0);
  const double printed = 18.0 - std::sqrt(324.0 - 6.0 * 6.0);
  const auto res = compute_entry_length(
      entry_exit(36.0, -4.0, straight_contour(20.0), straight_contour(20.0), 60.0));
  ASSERT_TRUE(res.ok()) << outcome(res);
  EXPECT_NEAR(res.value().engagement_length_mm, right, kTol);
  EXPECT_GT(std::abs(res.value().engagement_length_mm - printed), 1.0);
  EXPECT_NEAR(res.value().start.y_mm, 6.0, kTol);
  ASSERT_TRUE(res.value().exit.has_value());
  EXPECT_NEAR(res.value().exit->end.x_mm, std::sqrt(324.0 - 196.0), kTol);
}

TEST(EntryLengthStraight, PerpendicularEdgesAreSymmetricInOffset) {
  struct Geometry {
    double D, B;
  };
  for (const Geometry g : {Geometry{20.0, 60.0}, Geometry{50.0, 25.0}, Geometry{30.0, 40.0},
                           Geometry{60.0, 20.0}, Geometry{7.0, 3.0}}) {
    for (double K : {0.5, 3.0, 7.25, 12.0, 19.0, 26.0}) {
      const auto plus = compute_entry_length(
          entry_exit(g.D, K, straight_contour(g.B), straight_contour(g.B), 500.0));
      const auto minus = compute_entry_length(
          entry_exit(g.D, -K, straight_contour(g.B), straight_contour(g.B), 500.0));
      ASSERT_EQ(plus.ok(), minus.ok()) << "D=" << g.D << " B=" << g.B << " K=" << K;
      if (!plus.ok()) {
        EXPECT_EQ(plus.error().code, ErrorCode::no_contact);
        EXPECT_EQ(minus.error().code, ErrorCode::no_contact);
        continue;
      }
      const auto& p = plus.value();
      const auto& m = minus.value();
      EXPECT_NEAR(p.engagement_length_mm, m.engagement_length_mm, kTol);
      EXPECT_NEAR(p.start.x_mm, m.start.x_mm, kTol);
      EXPECT_NEAR(p.steady_width_mm, m.steady_width_mm, kTol);
      EXPECT_NEAR(p.start.y_mm, g.B / 2.0 + K, kTol);
      EXPECT_NEAR(m.start.y_mm, g.B / 2.0 - K, kTol);
      ASSERT_TRUE(p.exit && m.exit);
      EXPECT_NEAR(p.exit->end.x_mm, m.exit->end.x_mm, kTol);
      EXPECT_NEAR(p.exit->working_stroke_mm, m.exit->working_stroke_mm, kTol);
    }
  }
}

TEST(EntryLengthStraight, TangentOffsetIsNoContact) {
  // |K| = h + r exactly: W = 0, "no contact" (E2, section 8).
  for (double K : {30.0, -30.0}) {
    const auto res = compute_entry_length(entry_only(20.0, K, straight_contour(40.0)));
    ASSERT_FALSE(res.ok()) << "K = " << K;
    EXPECT_EQ(res.error().code, ErrorCode::no_contact);
  }
  // Just inside: a 0.5 mm band, S3.
  const auto res = compute_entry_length(entry_only(20.0, 29.5, straight_contour(40.0)));
  ASSERT_TRUE(res.ok()) << outcome(res);
  EXPECT_NEAR(res.value().steady_width_mm, 0.5, kTol);
  EXPECT_NEAR(res.value().engagement_length_mm, std::sqrt(100.0 - 9.5 * 9.5), kTol);
}

TEST(EntryLengthStraight, OffsetBeyondReachIsNoContact) {
  const auto res = compute_entry_length(entry_only(20.0, -35.0, straight_contour(40.0)));
  ASSERT_FALSE(res.ok());
  EXPECT_EQ(res.error().code, ErrorCode::no_contact);
}

TEST(EntryLengthStraight, ApproachShiftsOnlyStartAndEntryLength) {
  const auto base = compute_entry_length(
      entry_exit(36.0, 4.0, straight_contour(20.0), straight_contour(20.0), 60.0, 0.0));
  const auto more = compute_entry_length(
      entry_exit(36.0, 4.0, straight_contour(20.0), straight_contour(20.0), 60.0, 3.5, 7.0, 1.0));
  ASSERT_TRUE(base.ok() && more.ok());
  EXPECT_NEAR(more.value().engagement_length_mm, base.value().engagement_length_mm, kTol);
  EXPECT_NEAR(more.value().entry_length_mm, base.value().engagement_length_mm + 3.5, kTol);
  EXPECT_NEAR(more.value().start.x_mm, base.value().start.x_mm + 3.5, kTol);
  ASSERT_TRUE(base.value().exit && more.value().exit);
  // E9: L_rx = L + L1 + X_n - X_k + L_per; base has L1 = 0, L_per = 2.
  EXPECT_NEAR(more.value().exit->working_stroke_mm,
              base.value().exit->working_stroke_mm + 3.5 + 7.0 + (1.0 - 2.0), kTol);
}

TEST(EntryLengthStraight, NinetyDegreeCotangentIsExactlyZero) {
  // cot(90) = 0 exactly (spec 6.2): on a wide strip S1 gives X_n = L_pod + r and X_k = 0 with no
  // rounding residue (cos(pi/2) = 6e-17 would leave ~1e-14 mm here). Exactness is normative.
  const auto res = compute_entry_length(
      entry_exit(20.0, 0.0, straight_contour(2000.0, 90.0), straight_contour(2000.0, 90.0), 100.0));
  ASSERT_TRUE(res.ok()) << outcome(res);
  EXPECT_NEAR(res.value().start.x_mm, 12.0, 0.0);
  EXPECT_NEAR(res.value().engagement_length_mm, 10.0, 0.0);
  ASSERT_TRUE(res.value().exit.has_value());
  EXPECT_NEAR(res.value().exit->end.x_mm, 0.0, 0.0);
}

TEST(EntryLengthStraight, BandEndsUseTheExactHalfChordArgument) {
  // Section 8: s(u) at a band end must use the exact u = +-r, not (K + r) - K, whose rounding
  // leaves sqrt(2 r ulp) ~ 1e-5 mm for large D and K. Band inside a wide strip (S1): L_vr1 = r,
  // X_n = L_pod + r and X_k = 0, for offsets and radii that are not exactly representable.
  for (double K : {12345.678901, -98765.4321, 333333.3}) {
    for (double D : {2000.2, 777.77, 123.456}) {
      const auto res = compute_entry_length(
          entry_exit(D, K, straight_contour(1e6), straight_contour(1e6), 1000.0));
      ASSERT_TRUE(res.ok()) << outcome(res);
      EXPECT_NEAR(res.value().engagement_length_mm, D / 2.0, kTol) << "K=" << K << " D=" << D;
      EXPECT_NEAR(res.value().start.x_mm, 2.0 + D / 2.0, kTol) << "K=" << K << " D=" << D;
      EXPECT_NEAR(res.value().steady_width_mm, D, 1e-9 * (1.0 + std::abs(K))) << "K=" << K;
      ASSERT_TRUE(res.value().exit.has_value());
      EXPECT_NEAR(res.value().exit->end.x_mm, 0.0, kTol) << "K=" << K << " D=" << D;
    }
  }
}

// ---- 6.2: inclined edges (E14-E16)
// ----------------------------------------------------------------

TEST(EntryLengthInclined, SixtyDegreesPositiveOffsetMatchesSpecSection11) {
  // alpha = 60, B = 40, D = 30, K = +10: L_vr1 = 11.914 (section 11).
  const auto res = compute_entry_length(entry_only(30.0, 10.0, straight_contour(40.0, 60.0)));
  ASSERT_TRUE(res.ok()) << outcome(res);
  EXPECT_NEAR(res.value().engagement_length_mm, 11.914, kSpec3);
  const auto expect = oracle::straight_entry(30.0, 40.0, 10.0, 60.0, 2.0);
  ASSERT_TRUE(expect.has_value());
  EXPECT_NEAR(res.value().engagement_length_mm, expect->engagement_mm, kTol);
  EXPECT_NEAR(res.value().start.x_mm, expect->start_x_mm, kTol);
  EXPECT_NEAR(res.value().start.y_mm, 30.0, kTol);
  EXPECT_NEAR(res.value().steady_width_mm, 25.0, kTol);
}

TEST(EntryLengthInclined, SixtyDegreesNegativeOffsetMatchesSpecSection11) {
  // Same edge, K = -10: L_vr1 = 25.981 (section 11); inclined edges are not symmetric in K.
  const auto res = compute_entry_length(entry_only(30.0, -10.0, straight_contour(40.0, 60.0)));
  ASSERT_TRUE(res.ok()) << outcome(res);
  EXPECT_NEAR(res.value().engagement_length_mm, 25.981, kSpec3);
  const auto expect = oracle::straight_entry(30.0, 40.0, -10.0, 60.0, 2.0);
  ASSERT_TRUE(expect.has_value());
  EXPECT_NEAR(res.value().engagement_length_mm, expect->engagement_mm, kTol);
  EXPECT_NEAR(res.value().start.x_mm, expect->start_x_mm, kTol);
  EXPECT_NEAR(res.value().start.y_mm, 10.0, kTol);
}

TEST(EntryLengthInclined, BandInsideStripMatchesE15) {
  // E15: L_vr1 = r (1 + |cos a|) / sin a; X_n = L_pod + r / sin a - (h + K) cot a.
  const double r = 10.0;
  const double h = 50.0;
  const double K = 10.0;
  for (double alpha : {30.0, 45.0, 75.0, 105.0, 135.0, 150.0}) {
    const double a = deg(alpha);
    const auto res = compute_entry_length(entry_only(20.0, K, straight_contour(100.0, alpha)));
    ASSERT_TRUE(res.ok()) << outcome(res);
    EXPECT_NEAR(res.value().engagement_length_mm, r * (1.0 + std::abs(std::cos(a))) / std::sin(a),
                kTol)
        << "alpha = " << alpha;
    EXPECT_NEAR(res.value().start.x_mm, 2.0 + r / std::sin(a) - (h + K) / std::tan(a), kTol)
        << "alpha = " << alpha;
    EXPECT_NEAR(res.value().start.y_mm, h + K, kTol);
    EXPECT_NEAR(res.value().steady_width_mm, 2.0 * r, kTol);
  }
}

TEST(EntryLengthInclined, SupplementaryAnglesHaveEqualEngagementInsideTheStrip) {
  // |cos a| in E15: alpha and 180 - alpha give the same L_vr1 when the band is inside the strip.
  for (double alpha : {20.0, 50.0, 80.0}) {
    const auto acute = compute_entry_length(entry_only(20.0, -5.0, straight_contour(100.0, alpha)));
    const auto obtuse =
        compute_entry_length(entry_only(20.0, -5.0, straight_contour(100.0, 180.0 - alpha)));
    ASSERT_TRUE(acute.ok() && obtuse.ok());
    EXPECT_NEAR(acute.value().engagement_length_mm, obtuse.value().engagement_length_mm, kTol);
  }
}

TEST(EntryLengthInclined, NearlyPerpendicularEdgeTendsToOneRadius) {
  // Section 11 / T1 row 7 errata (H10): alpha = 89.9, r = 10 -> L_vr1 = 10.0175; the printed
  // (D/2)(tg a + sin a) would give ~5740 mm.
  const auto res = compute_entry_length(entry_only(20.0, 0.0, straight_contour(100.0, 89.9)));
  ASSERT_TRUE(res.ok()) << outcome(res);
  EXPECT_NEAR(res.value().engagement_length_mm, 10.0175, 5e-5);
  const double a = deg(89.9);
  EXPECT_NEAR(res.value().engagement_length_mm, 10.0 * (1.0 + std::cos(a)) / std::sin(a), kTol);
  const double printed = 10.0 * (std::tan(a) + std::sin(a));
  EXPECT_GT(std::abs(res.value().engagement_length_mm - printed), 1000.0);
}

TEST(EntryLengthInclined, NotSymmetricInOffset) {
  const auto plus = compute_entry_length(entry_only(30.0, 10.0, straight_contour(40.0, 60.0)));
  const auto minus = compute_entry_length(entry_only(30.0, -10.0, straight_contour(40.0, 60.0)));
  ASSERT_TRUE(plus.ok() && minus.ok());
  EXPECT_GT(std::abs(plus.value().engagement_length_mm - minus.value().engagement_length_mm), 10.0);
}

TEST(EntryLengthInclined, SmallAngleStartsDownstreamOfTheCorner) {
  // Section 3 (H11): alpha = 10, B = 60, D = 20, K = 0 -> X_n = -110.55 (E15).
  const auto res = compute_entry_length(entry_only(20.0, 0.0, straight_contour(60.0, 10.0)));
  ASSERT_TRUE(res.ok()) << outcome(res);
  EXPECT_NEAR(res.value().start.x_mm, -110.55, kSpec2);
  const double a = deg(10.0);
  EXPECT_NEAR(res.value().start.x_mm, 2.0 + 10.0 / std::sin(a) - 30.0 / std::tan(a), kTol);
  EXPECT_LT(res.value().start.x_mm, 0.0);
}

TEST(EntryLengthInclined, InclinedExitPassesBeyondTheExitOrigin) {
  // Section 3 (H26): exit alpha_x = 60, B = 60, D = 20, K = 0 -> X_k = -23.09 (E16 band inside:
  // X_k = -(h + K) cot a_x - r |cot a_x|).
  const auto res = compute_entry_length(
      entry_exit(20.0, 0.0, straight_contour(60.0), straight_contour(60.0, 60.0), 100.0));
  ASSERT_TRUE(res.ok()) << outcome(res);
  ASSERT_TRUE(res.value().exit.has_value());
  const double cot = 1.0 / std::tan(deg(60.0));
  EXPECT_NEAR(res.value().exit->end.x_mm, -23.09, kSpec2);
  EXPECT_NEAR(res.value().exit->end.x_mm, -30.0 * cot - 10.0 * cot, kTol);
  EXPECT_NEAR(res.value().exit->end.y_mm, 30.0, kTol);
  EXPECT_NEAR(res.value().exit->working_stroke_mm, 100.0 + 12.0 + (30.0 + 10.0) * cot + 2.0, kTol);
}

TEST(EntryLengthInclined, ObtuseExitStopsShortOfTheExitOrigin) {
  // alpha_x = 120: cot < 0; band inside: X_k = -(h + K) cot - r |cot| > 0 here.
  const auto res = compute_entry_length(
      entry_exit(20.0, 5.0, straight_contour(60.0), straight_contour(60.0, 120.0), 100.0));
  ASSERT_TRUE(res.ok()) << outcome(res);
  ASSERT_TRUE(res.value().exit.has_value());
  const double cot = 1.0 / std::tan(deg(120.0));
  EXPECT_NEAR(res.value().exit->end.x_mm, -35.0 * cot - 10.0 * std::abs(cot), kTol);
  EXPECT_GT(res.value().exit->end.x_mm, 0.0);
}

TEST(EntryLengthInclined, BandClippedBySideEdgesMatchesE14AndE16) {
  // Bands clipped at one or both side edges: only the general E14/E16 apply.
  struct Case {
    double D, B, K, alpha, alpha_x;
  };
  for (const Case c : {Case{30.0, 40.0, 10.0, 60.0, 60.0}, Case{30.0, 40.0, -10.0, 120.0, 45.0},
                       Case{80.0, 30.0, 0.0, 35.0, 140.0}, Case{80.0, 30.0, 20.0, 150.0, 20.0},
                       Case{10.0, 30.0, 17.0, 70.0, 100.0}, Case{10.0, 30.0, -17.0, 70.0, 100.0}}) {
    const auto res = compute_entry_length(entry_exit(c.D, c.K, straight_contour(c.B, c.alpha),
                                                     straight_contour(c.B, c.alpha_x), 300.0));
    ASSERT_TRUE(res.ok()) << outcome(res);
    const auto e = oracle::straight_entry(c.D, c.B, c.K, c.alpha, 2.0);
    const auto x = oracle::straight_exit(c.D, c.B, c.K, c.alpha_x);
    ASSERT_TRUE(e && x);
    const auto& v = res.value();
    EXPECT_NEAR(v.engagement_length_mm, e->engagement_mm, kTol) << "alpha " << c.alpha;
    EXPECT_NEAR(v.start.x_mm, e->start_x_mm, kTol) << "alpha " << c.alpha;
    EXPECT_NEAR(v.start.y_mm, e->start_y_mm, kTol);
    EXPECT_NEAR(v.steady_width_mm, e->steady_width_mm, kTol);
    ASSERT_TRUE(v.exit.has_value());
    EXPECT_NEAR(v.exit->end.x_mm, x->end_x_mm, kTol) << "alpha_x " << c.alpha_x;
    EXPECT_NEAR(v.exit->working_stroke_mm, 300.0 + e->start_x_mm - x->end_x_mm + 2.0, kTol);
  }
}
