#pragma once
// Request builders and a result accessor shared by the resultant-speed tests
// (spec shared/domain/resultant-speeds.md).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

#include "domain/common/numeric.h"
#include "domain/kinematics/resultant_speeds.h"

namespace cutcalc::test::kinematics {

using domain::MillingSense;
using domain::kinematics::CenterDistance;
using domain::kinematics::ContactPointSpeeds;
using domain::kinematics::FlatDepth;
using domain::kinematics::ResultantSpeedsParams;
using domain::kinematics::ResultantSpeedsResult;

inline constexpr double kPi = std::numbers::pi;
inline double radians(double deg) { return domain::deg_to_rad(deg); }
inline double degrees(double rad) { return domain::rad_to_deg(rad); }

// The paper's flat (section 6): D32 part, flat 1 mm deep (a_w = 25), R1 = 10 end mill at
// 3000 rpm, part at 10 rpm, tool feed +100 mm/min, default points.
inline ResultantSpeedsParams sample(MillingSense milling, double feed_mm_per_min = 100.0) {
  ResultantSpeedsParams p;
  p.tool_radius_mm = 10.0;
  p.workpiece_radius_mm = 16.0;
  p.placement = FlatDepth{1.0};
  p.tool_speed_rpm = 3000.0;
  p.workpiece_speed_rpm = 10.0;
  p.milling = milling;
  p.tool_feed_mm_per_min = feed_mm_per_min;
  return p;
}

// A request on a centre distance with the sample's speeds and feed.
inline ResultantSpeedsParams on_center_distance(double R1, double R2, double a_w,
                                                MillingSense milling) {
  ResultantSpeedsParams p = sample(milling);
  p.tool_radius_mm = R1;
  p.workpiece_radius_mm = R2;
  p.placement = CenterDistance{a_w};
  return p;
}

// A request on a flat depth with the sample's speeds and feed.
inline ResultantSpeedsParams on_flat_depth(double R1, double R2, double t, MillingSense milling) {
  ResultantSpeedsParams p = sample(milling);
  p.tool_radius_mm = R1;
  p.workpiece_radius_mm = R2;
  p.placement = FlatDepth{t};
  return p;
}

inline ResultantSpeedsParams with_angles(ResultantSpeedsParams p, std::vector<double> angles) {
  p.contact_angles_deg = std::move(angles);
  return p;
}

// The computed result; a domain error is a test failure and yields an empty result, so callers
// ASSERT on the number of points before indexing.
inline ResultantSpeedsResult computed(const ResultantSpeedsParams& params) {
  auto result = domain::kinematics::compute_resultant_speeds(params);
  if (!result.ok()) {
    ADD_FAILURE() << "unexpected domain error: " << result.error().detail;
    return {};
  }
  return std::move(result.value());
}

// Relative tolerance with an absolute floor, as the reference comparison rule.
inline double tol(double want, double rel, double abs_floor = 1e-12) {
  return std::max(abs_floor, rel * std::abs(want));
}

inline bool all_finite(const ContactPointSpeeds& p) {
  for (const double x :
       {p.contact_angle_deg, p.contact_radius_mm, p.contact_polar_angle_deg, p.tool_speed_m_per_min,
        p.workpiece_speed_m_per_min, p.resultant_feed_mm_per_min, p.resultant_speed_m_per_min,
        p.resultant_angle_deg, p.kinematic_ratio, p.normal_speed_m_per_min,
        p.along_edge_speed_m_per_min}) {
    if (!std::isfinite(x)) {
      return false;
    }
  }
  return true;
}

}  // namespace cutcalc::test::kinematics
