// Unit tests: wall exit (E22), working stroke limits (E23) and the error codes of
// compute_entry_length (spec entry-and-main-time.md 6.5, 6.6, 8).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "domain/entry/entry_length.h"
#include "domain/entry/entry_test_support.h"

namespace {

using cutcalc::domain::ErrorCode;
using cutcalc::domain::entry::compute_entry_length;
using cutcalc::test::concave_contour;
using cutcalc::test::convex_contour;
using cutcalc::test::entry_exit;
using cutcalc::test::entry_only;
using cutcalc::test::outcome;
using cutcalc::test::straight_contour;
using cutcalc::test::wall_contour;

using cutcalc::test::kTol;

template <class R>
void expect_error(const R& res, ErrorCode code, const char* what) {
  ASSERT_FALSE(res.ok()) << what << ": expected " << cutcalc::domain::error_code_name(code);
  EXPECT_EQ(res.error().code, code) << what << ": got " << outcome(res);
}

}  // namespace

// ---- 6.5 wall exit
// -------------------------------------------------------------------------------

TEST(EntryLengthWallExit, StopsWithThePeripheryAtTheWall) {
  // D = 20, B = 60, K = 0, L = 100: X_k = r = 10, L_per = 0 -> L_rx = 100 + 12 - 10 = 102.
  const auto res = compute_entry_length(
      entry_exit(20.0, 0.0, straight_contour(60.0), wall_contour(60.0), 100.0));
  ASSERT_TRUE(res.ok()) << outcome(res);
  ASSERT_TRUE(res.value().exit.has_value());
  EXPECT_NEAR(res.value().exit->end.x_mm, 10.0, kTol);
  EXPECT_NEAR(res.value().exit->end.y_mm, 30.0, kTol);
  EXPECT_NEAR(res.value().exit->working_stroke_mm, 102.0, kTol);
}

TEST(EntryLengthWallExit, OverrunIsIgnored) {
  const auto two = compute_entry_length(
      entry_exit(20.0, 0.0, straight_contour(60.0), wall_contour(60.0), 100.0, 2.0, 0.0, 2.0));
  const auto seven = compute_entry_length(
      entry_exit(20.0, 0.0, straight_contour(60.0), wall_contour(60.0), 100.0, 2.0, 0.0, 7.0));
  ASSERT_TRUE(two.ok() && seven.ok());
  ASSERT_TRUE(two.value().exit && seven.value().exit);
  EXPECT_NEAR(seven.value().exit->working_stroke_mm, two.value().exit->working_stroke_mm, kTol);
  EXPECT_NEAR(seven.value().exit->working_stroke_mm, 102.0, kTol);
}

TEST(EntryLengthWallExit, EndYIsMeasuredFromTheSideEdge) {
  // Y_k = h_x + K also behind a convex entry (whose Y_n is measured from the arc axis).
  const auto res = compute_entry_length(
      entry_exit(20.0, 5.0, convex_contour(30.0), wall_contour(60.0), 100.0, 2.0, 4.0));
  ASSERT_TRUE(res.ok()) << outcome(res);
  ASSERT_TRUE(res.value().exit.has_value());
  EXPECT_NEAR(res.value().start.y_mm, 5.0, kTol);
  EXPECT_NEAR(res.value().exit->end.x_mm, 10.0, kTol);
  EXPECT_NEAR(res.value().exit->end.y_mm, 35.0, kTol);
  EXPECT_NEAR(res.value().exit->working_stroke_mm,
              100.0 + 4.0 + res.value().start.x_mm - 10.0 + 0.0, kTol);
}

// ---- 6.6 / E23: stroke shorter than the entry
// -------------------------------------------------------

TEST(EntryLengthErrors, StrokeEndingExactlyAtSaturationIsAccepted) {
  // Wall exit, S1: x_cs = 0, X_k = r = 10; L = 10, L1 = 0 -> steady travel exactly 0 (not < 0).
  const auto res =
      compute_entry_length(entry_exit(20.0, 0.0, straight_contour(60.0), wall_contour(60.0), 10.0));
  ASSERT_TRUE(res.ok()) << outcome(res);
  ASSERT_TRUE(res.value().exit.has_value());
  EXPECT_NEAR(res.value().exit->working_stroke_mm, res.value().entry_length_mm, kTol);
  EXPECT_NEAR(res.value().exit->working_stroke_mm, 12.0, kTol);
}

TEST(EntryLengthErrors, StrokeShorterThanEntryIsRejected) {
  expect_error(
      compute_entry_length(entry_exit(20.0, 0.0, straight_contour(60.0), wall_contour(60.0), 9.5)),
      ErrorCode::stroke_shorter_than_entry, "wall, L = 9.5");
  // With a perpendicular exit the steady travel is never negative (x_cs = -X_k for alpha = 90), so
  // use an exit that ends downstream of its origin: alpha_x = 150 (cot < 0), B = 60, K = 0, r = 10:
  // E16 band inside X_k = -(h + K) cot - r |cot| = 20 sqrt(3); steady travel = L + 2 - 0 - X_k.
  const double cot150 = 1.0 / std::tan(150.0 * std::numbers::pi / 180.0);
  const double end = -30.0 * cot150 - 10.0 * std::abs(cot150);
  ASSERT_GT(end, 20.0);
  expect_error(compute_entry_length(entry_exit(20.0, 0.0, straight_contour(60.0),
                                               straight_contour(60.0, 150.0), end - 3.0 - 2.0)),
               ErrorCode::stroke_shorter_than_entry, "alpha_x = 150");
  const auto ok = compute_entry_length(entry_exit(20.0, 0.0, straight_contour(60.0),
                                                  straight_contour(60.0, 150.0), end - 2.0 + 1.0));
  EXPECT_TRUE(ok.ok()) << outcome(ok);
}

// ---- section 8: combination errors
// -------------------------------------------------------------------

TEST(EntryLengthErrors, NoContactForEveryContour) {
  expect_error(compute_entry_length(entry_only(20.0, 30.0, straight_contour(40.0))),
               ErrorCode::no_contact, "straight tangency");
  expect_error(compute_entry_length(entry_only(20.0, -31.0, straight_contour(40.0, 70.0))),
               ErrorCode::no_contact, "inclined beyond reach");
  expect_error(compute_entry_length(entry_only(16.0, 28.0, convex_contour(20.0))),
               ErrorCode::no_contact, "convex tangency");
  expect_error(compute_entry_length(entry_only(16.0, -23.0, convex_contour(20.0, 30.0))),
               ErrorCode::no_contact, "partial convex tangency at h = 15");
  expect_error(compute_entry_length(entry_only(10.0, 15.0, concave_contour(12.0, 20.0))),
               ErrorCode::no_contact, "concave tangency");
  expect_error(compute_entry_length(
                   entry_exit(20.0, 30.0, straight_contour(40.0), wall_contour(40.0), 100.0)),
               ErrorCode::no_contact, "with a wall exit");
}

TEST(EntryLengthErrors, ExitWidthMustEqualEntryWidth) {
  expect_error(compute_entry_length(
                   entry_exit(20.0, 0.0, straight_contour(40.0), straight_contour(50.0), 100.0)),
               ErrorCode::exit_width_mismatch, "straight 40 -> straight 50");
  expect_error(compute_entry_length(
                   entry_exit(20.0, 0.0, convex_contour(20.0), straight_contour(41.0), 100.0)),
               ErrorCode::exit_width_mismatch, "convex 2R = 40 -> straight 41");
  expect_error(compute_entry_length(
                   entry_exit(20.0, 0.0, straight_contour(40.0), convex_contour(25.0), 100.0)),
               ErrorCode::exit_width_mismatch, "straight 40 -> convex 2R = 50");
  expect_error(compute_entry_length(entry_exit(20.0, 0.0, straight_contour(40.0),
                                               wall_contour(40.0 * (1.0 + 1e-7)), 100.0)),
               ErrorCode::exit_width_mismatch, "relative difference 1e-7 > 1e-9");
}

TEST(EntryLengthErrors, ExitWidthComparisonHasRelativeToleranceOf1e9) {
  const auto res = compute_entry_length(
      entry_exit(20.0, 0.0, straight_contour(40.0), straight_contour(40.0 * (1.0 + 1e-12)), 100.0));
  EXPECT_TRUE(res.ok()) << outcome(res);
  const auto arc = compute_entry_length(
      entry_exit(20.0, 0.0, straight_contour(40.0), convex_contour(20.0), 100.0));
  EXPECT_TRUE(arc.ok()) << outcome(arc);
}

TEST(EntryLengthErrors, EntryArcWiderThanDiameter) {
  expect_error(compute_entry_length(entry_only(20.0, 0.0, convex_contour(10.0, 25.0))),
               ErrorCode::entry_arc_wider_than_diameter, "convex R = 10, width 25");
  expect_error(compute_entry_length(entry_only(20.0, 0.0, concave_contour(10.0, 25.0))),
               ErrorCode::entry_arc_wider_than_diameter, "concave R = 10, width 25");
  // width = 2R is allowed.
  const auto ok = compute_entry_length(entry_only(20.0, 0.0, concave_contour(10.0, 20.0)));
  EXPECT_TRUE(ok.ok()) << outcome(ok);
}

TEST(EntryLengthErrors, ExitArcWiderThanDiameter) {
  expect_error(compute_entry_length(entry_exit(20.0, 0.0, straight_contour(25.0),
                                               convex_contour(10.0, 25.0), 100.0)),
               ErrorCode::exit_arc_wider_than_diameter, "convex exit R = 10, width 25");
  expect_error(compute_entry_length(entry_exit(20.0, 0.0, straight_contour(25.0),
                                               concave_contour(10.0, 25.0), 100.0)),
               ErrorCode::exit_arc_wider_than_diameter, "concave exit R = 10, width 25");
}

TEST(EntryLengthErrors, WithoutAnExitThereIsNoEndOrStroke) {
  const auto res = compute_entry_length(entry_only(20.0, 0.0, straight_contour(60.0)));
  ASSERT_TRUE(res.ok()) << outcome(res);
  EXPECT_FALSE(res.value().exit.has_value());
  EXPECT_NEAR(res.value().engagement_length_mm, 10.0, kTol);
}
