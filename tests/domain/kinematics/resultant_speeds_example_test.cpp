// The worked example of spec resultant-speeds.md section 6: the paper's 1 mm flat on a D32 part,
// up and down. The table is printed rounded, so its numbers are checked to half a unit of their
// last digit; closed forms of the same geometry pin the values to 1e-12.

#include <gtest/gtest.h>

#include <cmath>

#include "domain/kinematics/resultant_speeds_test_support.h"

namespace {

using cutcalc::test::kinematics::computed;
using cutcalc::test::kinematics::ContactPointSpeeds;
using cutcalc::test::kinematics::degrees;
using cutcalc::test::kinematics::MillingSense;
using cutcalc::test::kinematics::radians;
using cutcalc::test::kinematics::sample;
using cutcalc::test::kinematics::tol;

// One printed row of the section 6 table.
struct ExampleRow {
  double rho_deg;
  double contact_radius_mm;
  double sigma_deg;
  double workpiece_speed_m_per_min;
  double resultant_feed_mm_per_min;
  double resultant_speed_m_per_min;
};

// Half a unit of the last printed digit of each column.
void expect_row(const ContactPointSpeeds& got, const ExampleRow& want) {
  EXPECT_NEAR(got.contact_angle_deg, want.rho_deg, 5e-5);
  EXPECT_NEAR(got.contact_radius_mm, want.contact_radius_mm, 1e-12 * want.contact_radius_mm);
  EXPECT_NEAR(got.contact_polar_angle_deg, want.sigma_deg, 5e-5);
  EXPECT_NEAR(got.workpiece_speed_m_per_min, want.workpiece_speed_m_per_min, 5e-6);
  EXPECT_NEAR(got.resultant_feed_mm_per_min, want.resultant_feed_mm_per_min, 5e-4);
  EXPECT_NEAR(got.resultant_speed_m_per_min, want.resultant_speed_m_per_min, 5e-5);
}

TEST(ResultantSpeedsExample, EngagementHalfAngleAndToolSpeed) {
  const auto result = computed(sample(MillingSense::up));
  // V3 in closed form: cos rho_e = (25^2 + 10^2 - 16^2) / (2 25 10) = 0.938, well away from +-1.
  const double rho_e = degrees(std::acos(0.938));
  EXPECT_NEAR(result.engagement_half_angle_deg, 20.2816, 5e-5);
  EXPECT_NEAR(result.engagement_half_angle_deg, rho_e, tol(rho_e, 1e-12));
  ASSERT_EQ(result.points.size(), 3u);
  // Section 3: the default points are +rho_e, 0, -rho_e with the very rho_e reported.
  EXPECT_EQ(result.points[0].contact_angle_deg, result.engagement_half_angle_deg);
  EXPECT_EQ(result.points[1].contact_angle_deg, 0.0);
  EXPECT_EQ(result.points[2].contact_angle_deg, -result.engagement_half_angle_deg);
  const double V_T = 2.0 * std::numbers::pi * 10.0 * 3000.0 / 1000.0;  // V8, m/min
  for (const auto& point : result.points) {
    EXPECT_NEAR(point.tool_speed_m_per_min, 188.4956, 5e-5);
    EXPECT_NEAR(point.tool_speed_m_per_min, V_T, tol(V_T, 1e-14));
  }
}

TEST(ResultantSpeedsExample, UpMillingTable) {
  const auto result = computed(sample(MillingSense::up));
  ASSERT_EQ(result.points.size(), 3u);
  expect_row(result.points[0], {20.2816, 16.0, 12.5122, 1.00531, 1031.604, 189.3071});
  expect_row(result.points[1], {0.0, 15.0, 0.0, 0.94248, 947.768, 189.4381});
  expect_row(result.points[2], {-20.2816, 16.0, -12.5122, 1.00531, 988.478, 189.3758});
  for (const auto& point : result.points) {
    EXPECT_EQ(point.sense, MillingSense::up);
  }
}

TEST(ResultantSpeedsExample, DownMillingTable) {
  const auto result = computed(sample(MillingSense::down));
  ASSERT_EQ(result.points.size(), 3u);
  expect_row(result.points[0], {20.2816, 16.0, 12.5122, 1.00531, 988.478, 187.6163});
  expect_row(result.points[1], {0.0, 15.0, 0.0, 0.94248, 947.768, 187.5531});
  expect_row(result.points[2], {-20.2816, 16.0, -12.5122, 1.00531, 1031.604, 187.6862});
  for (const auto& point : result.points) {
    EXPECT_EQ(point.sense, MillingSense::down);
  }
}

TEST(ResultantSpeedsExample, KinematicRatioAndResultantAngleAreSmall) {
  for (const auto milling : {MillingSense::up, MillingSense::down}) {
    const auto result = computed(sample(milling));
    ASSERT_EQ(result.points.size(), 3u);
    // V13: i_k = 2 pi R2' n2 / (2 pi R1 n1) = R2' / 3000 with R2' = 16, 15, 16.
    EXPECT_NEAR(result.points[0].kinematic_ratio, 16.0 / 3000.0, 1e-15);
    EXPECT_NEAR(result.points[1].kinematic_ratio, 0.005, 1e-15);
    EXPECT_NEAR(result.points[2].kinematic_ratio, 16.0 / 3000.0, 1e-15);
    for (const auto& point : result.points) {
      EXPECT_GE(point.kinematic_ratio, 0.0050 - 1e-15);
      EXPECT_LE(point.kinematic_ratio, 0.0054);
      EXPECT_LT(std::abs(point.resultant_angle_deg), 0.2);
      // lambda = 0: all of |v_e| is normal to the edge.
      EXPECT_EQ(point.normal_speed_m_per_min, point.resultant_speed_m_per_min);
      EXPECT_EQ(point.along_edge_speed_m_per_min, 0.0);
    }
  }
}

// Section 4 notes: at the middle with a_w > R1, |v_e|^2 = (V_T +- v_S2)^2 + v_s1^2 (+ up, - down),
// and v_s1 is perpendicular to v_w, so |u_s| = hypot(v_s1, v_S2).
TEST(ResultantSpeedsExample, MiddlePointMatchesClosedForm) {
  const double V_T = 2.0 * std::numbers::pi * 10.0 * 3000.0;  // mm/min
  const double v_S2 = 2.0 * std::numbers::pi * 15.0 * 10.0;   // mm/min, R2' = a_w - R1 = 15
  const double v_s1 = 100.0;
  const auto up = computed(sample(MillingSense::up));
  const auto down = computed(sample(MillingSense::down));
  ASSERT_EQ(up.points.size(), 3u);
  ASSERT_EQ(down.points.size(), 3u);
  const double up_ve = std::hypot(V_T + v_S2, v_s1) / 1000.0;
  const double down_ve = std::hypot(V_T - v_S2, v_s1) / 1000.0;
  EXPECT_NEAR(up.points[1].resultant_speed_m_per_min, up_ve, tol(up_ve, 1e-12));
  EXPECT_NEAR(down.points[1].resultant_speed_m_per_min, down_ve, tol(down_ve, 1e-12));
  const double u_s = std::hypot(v_s1, v_S2);
  EXPECT_NEAR(up.points[1].resultant_feed_mm_per_min, u_s, tol(u_s, 1e-12));
  EXPECT_NEAR(down.points[1].resultant_feed_mm_per_min, u_s, tol(u_s, 1e-12));
  // V11 at rho = 0: atan2(v_s1, V_T +- v_S2).
  EXPECT_NEAR(up.points[1].resultant_angle_deg, degrees(std::atan2(v_s1, V_T + v_S2)), 1e-14);
  EXPECT_NEAR(down.points[1].resultant_angle_deg, degrees(std::atan2(v_s1, V_T - v_S2)), 1e-14);
}

// Erratum E1: paper eq. (4) as printed (|u_s1| |u_s2| cos of their angle) gives 0 at the middle,
// where the feed is perpendicular to the workpiece speed; the vector sum is 947.768 mm/min.
TEST(ResultantSpeedsExample, ErratumE1ResultantFeedIsTheVectorSum) {
  const auto result = computed(sample(MillingSense::up));
  ASSERT_EQ(result.points.size(), 3u);
  const double paper_eq4 = 100.0 * 942.4778 * std::cos(radians(90.0));
  EXPECT_NEAR(paper_eq4, 0.0, 1e-9);
  EXPECT_NEAR(result.points[1].resultant_feed_mm_per_min, 947.768, 5e-4);
}

// The exact geometry of the entry point: R2' = R2 and sigma from the law of sines (valid here,
// the contact point lies on the O1 side of the part axis).
TEST(ResultantSpeedsExample, EntryPointLiesOnTheWorkpieceCircle) {
  const auto result = computed(sample(MillingSense::down));
  ASSERT_EQ(result.points.size(), 3u);
  const double sin_rho_e = std::sqrt(1.0 - 0.938 * 0.938);
  const double sigma = degrees(std::asin(10.0 * sin_rho_e / 16.0));
  EXPECT_NEAR(result.points[0].contact_radius_mm, 16.0, 1e-12 * 16.0);
  EXPECT_NEAR(result.points[2].contact_radius_mm, 16.0, 1e-12 * 16.0);
  EXPECT_NEAR(result.points[0].contact_polar_angle_deg, sigma, tol(sigma, 1e-12));
  EXPECT_NEAR(result.points[2].contact_polar_angle_deg, -sigma, tol(sigma, 1e-12));
  EXPECT_EQ(result.points[1].contact_polar_angle_deg, 0.0);
}

}  // namespace
