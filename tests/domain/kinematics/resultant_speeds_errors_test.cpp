// The combination checks of spec resultant-speeds.md section 5: no contact (tested on a_w as given
// or on the flat depth t before forming a_w) and contact angles outside the engagement arc.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "domain/kinematics/resultant_speeds_test_support.h"

namespace {

using cutcalc::domain::ErrorCode;
using cutcalc::domain::kinematics::compute_resultant_speeds;
using cutcalc::test::kinematics::all_finite;
using cutcalc::test::kinematics::computed;
using cutcalc::test::kinematics::MillingSense;
using cutcalc::test::kinematics::on_center_distance;
using cutcalc::test::kinematics::on_flat_depth;
using cutcalc::test::kinematics::ResultantSpeedsParams;
using cutcalc::test::kinematics::sample;
using cutcalc::test::kinematics::with_angles;

constexpr double kInf = std::numeric_limits<double>::infinity();

void expect_no_contact(const ResultantSpeedsParams& params) {
  const auto result = compute_resultant_speeds(params);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().code, ErrorCode::no_contact);
  EXPECT_FALSE(result.error().index.has_value());
}

void expect_outside_arc(const ResultantSpeedsParams& params, std::size_t index) {
  const auto result = compute_resultant_speeds(params);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().code, ErrorCode::contact_angle_outside_arc);
  ASSERT_TRUE(result.error().index.has_value());
  EXPECT_EQ(*result.error().index, index);
}

// An arc that exists, however thin, with finite numbers everywhere and 0 < rho_e < 180.
void expect_valid_arc(const ResultantSpeedsParams& params) {
  const auto result = computed(params);
  EXPECT_GT(result.engagement_half_angle_deg, 0.0);
  EXPECT_LT(result.engagement_half_angle_deg, 180.0);
  ASSERT_EQ(result.points.size(), 3u);
  for (const auto& point : result.points) {
    EXPECT_TRUE(all_finite(point));
  }
}

// Reference case rs-err-no-contact and the boundaries a_w = R1 + R2 (outer tangency) and
// a_w = |R2 - R1| (inner tangency), both no contact; one step inside each is an arc.
TEST(ResultantSpeedsErrors, NoContactOnCenterDistance) {
  expect_no_contact(on_center_distance(10.0, 16.0, 26.0, MillingSense::up));
  expect_no_contact(on_center_distance(10.0, 16.0, 40.0, MillingSense::up));
  expect_no_contact(on_center_distance(10.0, 16.0, 6.0, MillingSense::up));
  expect_no_contact(on_center_distance(10.0, 16.0, 3.0, MillingSense::down));  // tool inside part
  expect_no_contact(on_center_distance(16.0, 10.0, 6.0, MillingSense::down));
  expect_no_contact(on_center_distance(16.0, 10.0, 2.0, MillingSense::up));  // part inside tool
  expect_no_contact(on_center_distance(10.0, 10.0, 20.0, MillingSense::up));
  expect_valid_arc(on_center_distance(10.0, 16.0, std::nextafter(26.0, 0.0), MillingSense::up));
  expect_valid_arc(on_center_distance(10.0, 16.0, std::nextafter(6.0, kInf), MillingSense::up));
  expect_valid_arc(on_center_distance(16.0, 10.0, std::nextafter(6.0, kInf), MillingSense::down));
  expect_valid_arc(on_center_distance(10.0, 10.0, 1e-300, MillingSense::up));  // rho_e ~ 90
}

// The flat depth is tested as given: t >= 2 min(R1, R2) is no contact, below it is an arc.
TEST(ResultantSpeedsErrors, NoContactOnFlatDepth) {
  expect_no_contact(on_flat_depth(10.0, 16.0, 20.0, MillingSense::up));
  expect_no_contact(on_flat_depth(10.0, 16.0, 25.0, MillingSense::up));
  expect_no_contact(on_flat_depth(20.0, 8.0, 16.0, MillingSense::down));
  expect_valid_arc(on_flat_depth(10.0, 16.0, std::nextafter(20.0, 0.0), MillingSense::up));
  expect_valid_arc(on_flat_depth(20.0, 8.0, std::nextafter(16.0, 0.0), MillingSense::down));
  expect_valid_arc(on_flat_depth(10.0, 16.0, 1e-300, MillingSense::up));
}

// Section 5: in doubles a_w = R2 - t + R1 can land on the other side of a boundary that t is
// strictly inside. Here a_w rounds to 39.879999999999995 < |R2 - R1| = 39.88, and for the
// shallow flat to R1 + R2; both still have an arc, with finite, valid numbers.
TEST(ResultantSpeedsErrors, FlatDepthInsideWhereRoundedCenterDistanceIsNot) {
  const double deep_t = std::nextafter(9.6, 0.0);
  ASSERT_LE(44.68 - deep_t + 4.8, std::abs(44.68 - 4.8));
  expect_valid_arc(on_flat_depth(4.8, 44.68, deep_t, MillingSense::up));

  const double shallow_t = 1.7763568394002505e-15;
  ASSERT_GE(23.097 - shallow_t + 48.114, 48.114 + 23.097);
  expect_valid_arc(on_flat_depth(48.114, 23.097, shallow_t, MillingSense::down));
}

// The default points use rho_e exactly as returned; feeding it back is inside the arc, and so is
// anything up to rho_e + 1e-9 deg, which is used as given (not clamped).
TEST(ResultantSpeedsErrors, AngleJustInsideTheArcIsAccepted) {
  const double rho_e = computed(sample(MillingSense::up)).engagement_half_angle_deg;
  const double just_inside = rho_e + 0.9e-9;
  const auto result =
      computed(with_angles(sample(MillingSense::up), {rho_e, -rho_e, just_inside, -just_inside}));
  ASSERT_EQ(result.points.size(), 4u);
  EXPECT_EQ(result.points[0].contact_angle_deg, rho_e);
  EXPECT_EQ(result.points[1].contact_angle_deg, -rho_e);
  EXPECT_EQ(result.points[2].contact_angle_deg, just_inside);
  EXPECT_EQ(result.points[3].contact_angle_deg, -just_inside);
  EXPECT_NEAR(result.points[2].contact_radius_mm, 16.0, 1e-8);
}

// Reference case rs-err-angle-outside-arc, and the first offending position is reported.
TEST(ResultantSpeedsErrors, AngleOutsideTheArcNamesItsIndex) {
  const double rho_e = computed(sample(MillingSense::up)).engagement_half_angle_deg;
  expect_outside_arc(with_angles(sample(MillingSense::up), {0.0, 30.0}), 1);
  expect_outside_arc(with_angles(sample(MillingSense::up), {rho_e + 1.1e-9}), 0);
  expect_outside_arc(with_angles(sample(MillingSense::up), {0.0, 5.0, -(rho_e + 1.1e-9), 10.0}), 2);
  expect_outside_arc(with_angles(sample(MillingSense::down), {1.0, 2.0, 3.0, 90.0, -90.0}), 3);
  expect_outside_arc(with_angles(sample(MillingSense::down), {1e300}), 0);
}

// No contact is decided before the angles are looked at.
TEST(ResultantSpeedsErrors, NoContactComesBeforeTheAngles) {
  expect_no_contact(
      with_angles(on_center_distance(10.0, 16.0, 26.0, MillingSense::up), {0.0, 45.0}));
}

}  // namespace
