// The local milling sense along the engagement arc (V6, V12, V15; erratum E3) of spec
// resultant-speeds.md.

#include <gtest/gtest.h>

#include <cmath>

#include "domain/kinematics/resultant_speeds_test_support.h"

namespace {

using cutcalc::test::kinematics::computed;
using cutcalc::test::kinematics::degrees;
using cutcalc::test::kinematics::MillingSense;
using cutcalc::test::kinematics::on_center_distance;
using cutcalc::test::kinematics::on_flat_depth;
using cutcalc::test::kinematics::ResultantSpeedsParams;
using cutcalc::test::kinematics::sample;
using cutcalc::test::kinematics::with_angles;

MillingSense opposite(MillingSense s) {
  return s == MillingSense::up ? MillingSense::down : MillingSense::up;
}

// Section 6 deep cut (case rs-deep-flip-default): R1 = 8, R2 = 20, t = 10, a_w = 18:
// rho_e = 92.388 deg, rho_f = arccos(8 / 18) = 63.612 deg; the ends have the opposite sense.
TEST(ResultantSpeedsSense, DeepCutFlipsSenseBeyondRhoF) {
  const double rho_f = degrees(std::acos(8.0 / 18.0));
  EXPECT_NEAR(rho_f, 63.612, 5e-4);
  for (const auto milling : {MillingSense::up, MillingSense::down}) {
    ResultantSpeedsParams p = on_flat_depth(8.0, 20.0, 10.0, milling);
    p.tool_speed_rpm = 5000.0;
    p.workpiece_speed_rpm = 40.0;
    p.tool_feed_mm_per_min = 150.0;
    const auto defaults = computed(p);
    EXPECT_NEAR(defaults.engagement_half_angle_deg, 92.388, 5e-4);
    // V3: cos rho_e = (18^2 + 8^2 - 20^2) / (2 18 8).
    EXPECT_NEAR(defaults.engagement_half_angle_deg, degrees(std::acos(-12.0 / 288.0)), 1e-12);
    ASSERT_EQ(defaults.points.size(), 3u);
    EXPECT_EQ(defaults.points[0].sense, opposite(milling));
    EXPECT_EQ(defaults.points[1].sense, milling);
    EXPECT_EQ(defaults.points[2].sense, opposite(milling));

    const auto around = computed(
        with_angles(p, {rho_f - 0.01, rho_f + 0.01, -(rho_f - 0.01), -(rho_f + 0.01), 30.0, 90.0}));
    ASSERT_EQ(around.points.size(), 6u);
    EXPECT_EQ(around.points[0].sense, milling);
    EXPECT_EQ(around.points[1].sense, opposite(milling));
    EXPECT_EQ(around.points[2].sense, milling);
    EXPECT_EQ(around.points[3].sense, opposite(milling));
    EXPECT_EQ(around.points[4].sense, milling);
    EXPECT_EQ(around.points[5].sense, opposite(milling));
  }
}

// Erratum E3: R1 = 10, R2 = 16, a_w = 17 is a deep cut (a_w^2 = 289 < 356 = R1^2 + R2^2):
// rho_f = 53.97 deg < rho_e = 66.97 deg.
TEST(ResultantSpeedsSense, ErratumE3DeepCutOnCenterDistance) {
  const double rho_f = degrees(std::acos(10.0 / 17.0));
  EXPECT_NEAR(rho_f, 53.97, 5e-3);
  for (const auto milling : {MillingSense::up, MillingSense::down}) {
    const auto result = computed(with_angles(on_center_distance(10.0, 16.0, 17.0, milling),
                                             {0.0, 53.9, 54.0, -53.9, -54.0, 66.9}));
    EXPECT_NEAR(result.engagement_half_angle_deg, 66.97, 5e-3);
    ASSERT_EQ(result.points.size(), 6u);
    EXPECT_EQ(result.points[0].sense, milling);
    EXPECT_EQ(result.points[1].sense, milling);
    EXPECT_EQ(result.points[2].sense, opposite(milling));
    EXPECT_EQ(result.points[3].sense, milling);
    EXPECT_EQ(result.points[4].sense, opposite(milling));
    EXPECT_EQ(result.points[5].sense, opposite(milling));
  }
}

// V12 notes: the sense is defined through s2, so a still part (n2 = 0) in a deep cut still
// reports the flip.
TEST(ResultantSpeedsSense, StillWorkpieceStillFlipsInDeepCut) {
  ResultantSpeedsParams p = on_flat_depth(8.0, 20.0, 10.0, MillingSense::down);
  p.workpiece_speed_rpm = 0.0;
  const auto result = computed(p);
  ASSERT_EQ(result.points.size(), 3u);
  EXPECT_EQ(result.points[0].sense, MillingSense::up);
  EXPECT_EQ(result.points[1].sense, MillingSense::down);
  EXPECT_EQ(result.points[2].sense, MillingSense::up);
}

// V15: a_w^2 >= R1^2 + R2^2 (the paper's shallow flat) keeps one sense along the whole arc.
TEST(ResultantSpeedsSense, ShallowCutKeepsOneSense) {
  for (const auto milling : {MillingSense::up, MillingSense::down}) {
    const auto result = computed(with_angles(sample(milling), {20.28, 15.0, 0.0, -10.0, -20.28}));
    ASSERT_EQ(result.points.size(), 5u);
    for (const auto& point : result.points) {
      EXPECT_EQ(point.sense, milling);
    }
  }
}

// V6/V12 as the sign of v_T . v_w: with down-milling on a_w > R1 the surfaces move the same way at
// the middle, i.e. |v_e| = V_T - v_S2 there (down is slower than up at the same point).
TEST(ResultantSpeedsSense, DownMeansSurfacesMoveTheSameWay) {
  const auto up = computed(with_angles(sample(MillingSense::up, 0.0), {0.0}));
  const auto down = computed(with_angles(sample(MillingSense::down, 0.0), {0.0}));
  ASSERT_EQ(up.points.size(), 1u);
  ASSERT_EQ(down.points.size(), 1u);
  const auto& u = up.points[0];
  const auto& d = down.points[0];
  EXPECT_NEAR(u.resultant_speed_m_per_min, u.tool_speed_m_per_min + u.workpiece_speed_m_per_min,
              1e-12);
  EXPECT_NEAR(d.resultant_speed_m_per_min, d.tool_speed_m_per_min - d.workpiece_speed_m_per_min,
              1e-12);
}

}  // namespace
