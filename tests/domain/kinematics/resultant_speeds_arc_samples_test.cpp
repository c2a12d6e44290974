// arc_samples of the resultant-speed request: contact angles evenly spaced over the whole
// engagement arc (spec resultant-speeds.md section 3: entry +rho_e, exit -rho_e), then the same
// point computation as for explicit contact angles.

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <vector>

#include "domain/kinematics/engagement_arc.h"
#include "domain/kinematics/resultant_speeds_test_support.h"

namespace {

using cutcalc::test::kinematics::computed;
using cutcalc::test::kinematics::ContactPointSpeeds;
using cutcalc::test::kinematics::MillingSense;
using cutcalc::test::kinematics::on_center_distance;
using cutcalc::test::kinematics::on_flat_depth;
using cutcalc::test::kinematics::ResultantSpeedsParams;
using cutcalc::test::kinematics::sample;
using cutcalc::test::kinematics::with_angles;
namespace kinematics_detail = cutcalc::domain::kinematics::detail;

ResultantSpeedsParams with_arc_samples(ResultantSpeedsParams p, int count) {
  p.arc_samples = count;
  return p;
}

// Every field of two points, bit for bit: the same angle must give the same computation.
void expect_same_point(const ContactPointSpeeds& got, const ContactPointSpeeds& want) {
  EXPECT_EQ(got.contact_angle_deg, want.contact_angle_deg);
  EXPECT_EQ(got.contact_radius_mm, want.contact_radius_mm);
  EXPECT_EQ(got.contact_polar_angle_deg, want.contact_polar_angle_deg);
  EXPECT_EQ(got.tool_speed_m_per_min, want.tool_speed_m_per_min);
  EXPECT_EQ(got.workpiece_speed_m_per_min, want.workpiece_speed_m_per_min);
  EXPECT_EQ(got.resultant_feed_mm_per_min, want.resultant_feed_mm_per_min);
  EXPECT_EQ(got.resultant_speed_m_per_min, want.resultant_speed_m_per_min);
  EXPECT_EQ(got.resultant_angle_deg, want.resultant_angle_deg);
  EXPECT_EQ(got.sense, want.sense);
  EXPECT_EQ(got.kinematic_ratio, want.kinematic_ratio);
  EXPECT_EQ(got.normal_speed_m_per_min, want.normal_speed_m_per_min);
  EXPECT_EQ(got.along_edge_speed_m_per_min, want.along_edge_speed_m_per_min);
}

// The paper's flat, a deep cut with the sense flip (section 6), the workpiece axis inside the
// tool circle, and a nearly tangent contact.
std::vector<ResultantSpeedsParams> setups() {
  return {sample(MillingSense::up), sample(MillingSense::down, -250.0),
          on_flat_depth(8.0, 20.0, 10.0, MillingSense::down),
          on_center_distance(10.0, 16.0, 8.0, MillingSense::up),
          on_center_distance(10.0, 16.0, 25.999999, MillingSense::down)};
}

TEST(ResultantSpeedsArcSamples, FirstAndLastPointsAreTheDefaultEntryAndExit) {
  for (const ResultantSpeedsParams& setup : setups()) {
    const auto defaults = computed(setup);
    ASSERT_EQ(defaults.points.size(), 3u);
    for (const int count : {2, 5, 361}) {
      SCOPED_TRACE(count);
      const auto sampled = computed(with_arc_samples(setup, count));
      ASSERT_EQ(sampled.points.size(), static_cast<std::size_t>(count));
      EXPECT_EQ(sampled.engagement_half_angle_deg, defaults.engagement_half_angle_deg);
      EXPECT_EQ(sampled.points.front().contact_angle_deg, sampled.engagement_half_angle_deg);
      EXPECT_EQ(sampled.points.back().contact_angle_deg, -sampled.engagement_half_angle_deg);
      expect_same_point(sampled.points.front(), defaults.points[0]);
      expect_same_point(sampled.points.back(), defaults.points[2]);
      if (count % 2 == 1) {
        expect_same_point(sampled.points[static_cast<std::size_t>(count / 2)], defaults.points[1]);
      }
    }
  }
}

TEST(ResultantSpeedsArcSamples, CountIsRightAndSpacingUniform) {
  for (const ResultantSpeedsParams& setup : setups()) {
    for (const int count : {2, 3, 4, 10, 181, 360, 361}) {
      SCOPED_TRACE(count);
      const auto sampled = computed(with_arc_samples(setup, count));
      ASSERT_EQ(sampled.points.size(), static_cast<std::size_t>(count));
      const double rho_e = sampled.engagement_half_angle_deg;
      const double spacing = 2.0 * rho_e / (count - 1);
      for (std::size_t i = 1; i < sampled.points.size(); ++i) {
        const double step =
            sampled.points[i - 1].contact_angle_deg - sampled.points[i].contact_angle_deg;
        EXPECT_NEAR(step, spacing, 1e-12 * rho_e) << i;
      }
      // Every sample lies on the arc: none is refused as outside it.
      for (const auto& point : sampled.points) {
        EXPECT_LE(std::abs(point.contact_angle_deg), rho_e);
      }
    }
  }
}

TEST(ResultantSpeedsArcSamples, ValuesEqualARequestWithTheSameExplicitAngles) {
  for (const ResultantSpeedsParams& setup : setups()) {
    const auto sampled = computed(with_arc_samples(setup, 37));
    ASSERT_EQ(sampled.points.size(), 37u);
    std::vector<double> angles;
    for (const auto& point : sampled.points) {
      angles.push_back(point.contact_angle_deg);
    }
    const auto explicit_angles = computed(with_angles(setup, angles));
    ASSERT_EQ(explicit_angles.points.size(), sampled.points.size());
    for (std::size_t i = 0; i < angles.size(); ++i) {
      SCOPED_TRACE(i);
      expect_same_point(sampled.points[i], explicit_angles.points[i]);
    }
  }
}

TEST(ResultantSpeedsArcSamples, DeepCutSamplesShowTheSenseFlip) {
  // Section 6, rs-deep-flip-default: rho_e = 92.388 deg, rho_f = 63.612 deg; with `milling`
  // down the middle is down and |rho| > rho_f is up (V15).
  const auto sampled =
      computed(with_arc_samples(on_flat_depth(8.0, 20.0, 10.0, MillingSense::down), 181));
  ASSERT_EQ(sampled.points.size(), 181u);
  const double rho_f = 63.612;
  for (const auto& point : sampled.points) {
    const double rho = std::abs(point.contact_angle_deg);
    if (rho < rho_f - 1e-3) {
      EXPECT_EQ(point.sense, MillingSense::down) << point.contact_angle_deg;
    } else if (rho > rho_f + 1e-3) {
      EXPECT_EQ(point.sense, MillingSense::up) << point.contact_angle_deg;
    }
  }
}

TEST(ResultantSpeedsArcSamples, AnglesAreAntisymmetricWithAnExactMiddle) {
  const double rho_e = 20.281649812950175;
  for (const int count : {2, 3, 8, 9, 100, 361}) {
    const std::vector<double> angles =
        kinematics_detail::evenly_spaced_contact_angles(rho_e, count);
    ASSERT_EQ(angles.size(), static_cast<std::size_t>(count));
    EXPECT_EQ(angles.front(), rho_e);
    EXPECT_EQ(angles.back(), -rho_e);
    for (std::size_t i = 0; i < angles.size(); ++i) {
      EXPECT_EQ(angles[i], -angles[angles.size() - 1 - i]) << count << " " << i;
      EXPECT_LE(std::abs(angles[i]), rho_e);
    }
    if (count % 2 == 1) {
      const double middle = angles[static_cast<std::size_t>(count / 2)];
      EXPECT_EQ(middle, 0.0);
      EXPECT_FALSE(std::signbit(middle));
    }
  }
  EXPECT_EQ(kinematics_detail::evenly_spaced_contact_angles(rho_e, 1), std::vector<double>{0.0});
  EXPECT_TRUE(kinematics_detail::evenly_spaced_contact_angles(rho_e, 0).empty());
}

TEST(ResultantSpeedsArcSamples, ArcSamplesAreUsedWhenBothListsAreSet) {
  // The API refuses both (422 at ""); the domain documents which one it would use.
  ResultantSpeedsParams both = with_arc_samples(sample(MillingSense::up), 4);
  both.contact_angles_deg = std::vector<double>{0.0};
  const auto result = computed(both);
  ASSERT_EQ(result.points.size(), 4u);
  EXPECT_EQ(result.points.front().contact_angle_deg, result.engagement_half_angle_deg);
}

}  // namespace
