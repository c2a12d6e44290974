// Contact geometry (V2, V4, V5), the feed sign, the still workpiece and the edge inclination
// (V14) of spec resultant-speeds.md.

#include <gtest/gtest.h>

#include <cmath>

#include "domain/kinematics/resultant_speeds_test_support.h"

namespace {

using cutcalc::test::kinematics::all_finite;
using cutcalc::test::kinematics::computed;
using cutcalc::test::kinematics::degrees;
using cutcalc::test::kinematics::MillingSense;
using cutcalc::test::kinematics::on_center_distance;
using cutcalc::test::kinematics::on_flat_depth;
using cutcalc::test::kinematics::radians;
using cutcalc::test::kinematics::ResultantSpeedsParams;
using cutcalc::test::kinematics::sample;
using cutcalc::test::kinematics::tol;
using cutcalc::test::kinematics::with_angles;

// Erratum E2: R1 = 10, a_w = 8, rho = 10 deg puts the contact point beyond the part axis
// (a_w - R1 cos rho < 0); atan2 gives sigma = 136.78 deg where the paper's arcsin gives 43.22.
TEST(ResultantSpeedsGeometry, ErratumE2PolarAngleBeyondNinetyDegrees) {
  const auto result =
      computed(with_angles(on_center_distance(10.0, 5.0, 8.0, MillingSense::up), {10.0, -10.0}));
  ASSERT_EQ(result.points.size(), 2u);
  const double x = 8.0 - 10.0 * std::cos(radians(10.0));
  const double y = 10.0 * std::sin(radians(10.0));
  const double R2_contact = std::sqrt(64.0 + 100.0 - 160.0 * std::cos(radians(10.0)));  // V4
  const double paper_eq3 = degrees(std::asin(y / R2_contact));
  EXPECT_NEAR(paper_eq3, 43.22, 5e-3);
  EXPECT_LT(x, 0.0);
  EXPECT_NEAR(result.points[0].contact_polar_angle_deg, 136.78, 5e-3);
  EXPECT_NEAR(result.points[0].contact_polar_angle_deg, 180.0 - paper_eq3, 1e-11);
  EXPECT_NEAR(result.points[1].contact_polar_angle_deg, -(180.0 - paper_eq3), 1e-11);
  EXPECT_NEAR(result.points[0].contact_radius_mm, R2_contact, tol(R2_contact, 1e-12));
}

// V5: the middle point of a deep cut with a_w < R1 lies on the negative X axis; sigma is +180,
// also for rho = -0.0, where atan2(-0, x < 0) would give -180.
TEST(ResultantSpeedsGeometry, PolarAngleOnNegativeAxisIsPlus180) {
  const auto result =
      computed(with_angles(on_center_distance(10.0, 5.0, 8.0, MillingSense::down), {0.0, -0.0}));
  ASSERT_EQ(result.points.size(), 2u);
  for (const auto& point : result.points) {
    EXPECT_EQ(point.contact_polar_angle_deg, 180.0);
    EXPECT_NEAR(point.contact_radius_mm, 2.0, 1e-15);
  }
}

// V5, V6, V12 with a_w = R1 (t = R2): the middle contact point is the workpiece axis. R2' = 0,
// sigma = 0, the workpiece speed there is 0 and g = 0 reports the requested sense; elsewhere
// g > 0 and s2 from the limit rho -> 0 keeps the requested sense along the whole arc.
TEST(ResultantSpeedsGeometry, CenterDistanceEqualToToolRadius) {
  for (const auto milling : {MillingSense::up, MillingSense::down}) {
    const auto result =
        computed(with_angles(on_flat_depth(10.0, 16.0, 16.0, milling), {0.0, 30.0, -30.0}));
    ASSERT_EQ(result.points.size(), 3u);
    // V3: cos rho_e = (100 + 100 - 256) / 200.
    EXPECT_NEAR(result.engagement_half_angle_deg, degrees(std::acos(-0.28)), 1e-12);
    EXPECT_EQ(result.points[0].contact_radius_mm, 0.0);
    EXPECT_EQ(result.points[0].contact_polar_angle_deg, 0.0);
    EXPECT_EQ(result.points[0].workpiece_speed_m_per_min, 0.0);
    EXPECT_EQ(result.points[0].kinematic_ratio, 0.0);
    // Isosceles triangle O2 O1 P: sigma = 90 - rho/2 for rho > 0.
    EXPECT_NEAR(result.points[1].contact_polar_angle_deg, 75.0, 1e-12);
    EXPECT_NEAR(result.points[2].contact_polar_angle_deg, -75.0, 1e-12);
    for (const auto& point : result.points) {
      EXPECT_EQ(point.sense, milling);
    }
  }
}

// V15: with the workpiece axis inside the tool circle (a_w < R1) g keeps its sign along the arc,
// so every point has the requested sense.
TEST(ResultantSpeedsGeometry, WorkpieceAxisInsideToolKeepsSense) {
  for (const auto milling : {MillingSense::up, MillingSense::down}) {
    const auto result = computed(on_center_distance(10.0, 5.0, 8.0, milling));
    ASSERT_EQ(result.points.size(), 3u);
    for (const auto& point : result.points) {
      EXPECT_EQ(point.sense, milling);
      EXPECT_TRUE(all_finite(point));
    }
  }
}

// V9: reversing the feed changes |u_s|^2 by 4 v_s1 omega2 R1 sin rho; at the middle (sin rho = 0)
// it only mirrors the resultant angle.
TEST(ResultantSpeedsGeometry, FeedSignEntersThroughTheCrossTerm) {
  for (const auto milling : {MillingSense::up, MillingSense::down}) {
    const auto forward = computed(sample(milling, 100.0));
    const auto backward = computed(sample(milling, -100.0));
    ASSERT_EQ(forward.points.size(), 3u);
    ASSERT_EQ(backward.points.size(), 3u);
    // a_w > R1: up = same rotation senses (omega2 > 0), down = opposite (V6).
    const double omega2 =
        (milling == MillingSense::up ? 1.0 : -1.0) * 2.0 * std::numbers::pi * 10.0;
    for (std::size_t i = 0; i < 3; ++i) {
      const double rho = radians(forward.points[i].contact_angle_deg);
      const double difference = 4.0 * 100.0 * omega2 * 10.0 * std::sin(rho);
      const double f = forward.points[i].resultant_feed_mm_per_min;
      const double b = backward.points[i].resultant_feed_mm_per_min;
      EXPECT_NEAR(f * f - b * b, difference, 1e-9 * f * f) << "point " << i;
      EXPECT_EQ(forward.points[i].sense, backward.points[i].sense);
    }
    EXPECT_NEAR(forward.points[1].resultant_angle_deg, -backward.points[1].resultant_angle_deg,
                1e-15);
    EXPECT_GT(forward.points[1].resultant_angle_deg, 0.0);
    EXPECT_NEAR(forward.points[1].resultant_speed_m_per_min,
                backward.points[1].resultant_speed_m_per_min, 1e-13);
  }
}

// Without feed the middle point's resultant speed is exactly along the edge speed (V11).
TEST(ResultantSpeedsGeometry, NoFeedGivesZeroAngleAtTheMiddle) {
  const auto result = computed(sample(MillingSense::down, 0.0));
  ASSERT_EQ(result.points.size(), 3u);
  EXPECT_EQ(result.points[1].resultant_angle_deg, 0.0);
  const double ve =
      (2.0 * std::numbers::pi * 10.0 * 3000.0 - 2.0 * std::numbers::pi * 15.0 * 10.0) / 1000.0;
  EXPECT_NEAR(result.points[1].resultant_speed_m_per_min, ve, tol(ve, 1e-13));
}

// n2 = 0 is plain milling of a still part: no workpiece speed, |u_s| = |v_s1|,
// |v_e|^2 = V_T^2 + v_s1^2 - 2 V_T v_s1 sin rho (V10), the sense from s2 (V12 notes).
TEST(ResultantSpeedsGeometry, StillWorkpiece) {
  for (const double feed : {100.0, -250.0}) {
    ResultantSpeedsParams p = sample(MillingSense::up, feed);
    p.workpiece_speed_rpm = 0.0;
    const auto result = computed(with_angles(p, {20.0, 0.0, -20.0, 7.5}));
    ASSERT_EQ(result.points.size(), 4u);
    const double V_T = 2.0 * std::numbers::pi * 10.0 * 3000.0;  // mm/min
    for (const auto& point : result.points) {
      const double rho = radians(point.contact_angle_deg);
      EXPECT_EQ(point.workpiece_speed_m_per_min, 0.0);
      EXPECT_EQ(point.kinematic_ratio, 0.0);
      EXPECT_NEAR(point.resultant_feed_mm_per_min, std::abs(feed), 1e-12);
      const double ve = std::sqrt(V_T * V_T + feed * feed - 2.0 * V_T * feed * std::sin(rho));
      EXPECT_NEAR(point.resultant_speed_m_per_min * 1000.0, ve, tol(ve, 1e-12));
      const double angle =
          degrees(std::atan2(feed * std::cos(rho), V_T - feed * std::sin(rho)));  // V11
      EXPECT_NEAR(point.resultant_angle_deg, angle, tol(angle, 1e-12));
      EXPECT_EQ(point.sense, MillingSense::up);
    }
  }
}

// V14 with lambda = 45 (the paper's example, erratum E6) and -30: both components, the
// along-edge one signed like lambda.
TEST(ResultantSpeedsGeometry, EdgeInclinationSplitsTheResultant) {
  struct Case {
    double lambda_deg;
    double normal_factor;
    double along_factor;
  };
  for (const Case c : {Case{45.0, std::sqrt(0.5), std::sqrt(0.5)},
                       Case{-30.0, std::sqrt(3.0) / 2.0, -0.5}, Case{0.0, 1.0, 0.0}}) {
    ResultantSpeedsParams p = sample(MillingSense::down);
    p.edge_inclination_deg = c.lambda_deg;
    const auto result = computed(with_angles(p, {-5.0, 5.0, 0.0, 20.0, 5.0}));
    ASSERT_EQ(result.points.size(), 5u);
    for (const auto& point : result.points) {
      const double ve = point.resultant_speed_m_per_min;
      EXPECT_NEAR(point.normal_speed_m_per_min, ve * c.normal_factor, tol(ve, 1e-15));
      EXPECT_NEAR(point.along_edge_speed_m_per_min, ve * c.along_factor, tol(ve, 1e-15));
    }
    // Duplicated angles are allowed and give the same point.
    EXPECT_EQ(result.points[1].resultant_speed_m_per_min,
              result.points[4].resultant_speed_m_per_min);
  }
}

// The paper's E6 example in numbers: 100 m/min at 45 deg gives 70.71 m/min for either component.
TEST(ResultantSpeedsGeometry, ErratumE6FortyFiveDegreeComponentsAreEqual) {
  ResultantSpeedsParams p = sample(MillingSense::up);
  p.edge_inclination_deg = 45.0;
  const auto result = computed(p);
  ASSERT_EQ(result.points.size(), 3u);
  for (const auto& point : result.points) {
    EXPECT_NEAR(point.normal_speed_m_per_min / point.resultant_speed_m_per_min * 100.0, 70.71,
                5e-3);
    EXPECT_NEAR(point.normal_speed_m_per_min, point.along_edge_speed_m_per_min,
                tol(point.normal_speed_m_per_min, 1e-15));
  }
}

}  // namespace
