// V1 and V3b of spec resultant-speeds.md with the no-contact rule of section 5.

#include "domain/kinematics/engagement_arc.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "domain/kinematics/degrees.h"

namespace cutcalc::domain::kinematics::detail {

namespace {

// Slack on |rho| <= rho_e: a rho_e copied from a response must be accepted whatever the last-bit
// rounding of the server's own rho_e (section 4 notes).
constexpr double kArcSlackDeg = 1e-9;

// V3b as 2 atan2(sqrt(inner), sqrt(outer)) with
//   inner = (R1 + R2 - a_w)(a_w + R2 - R1),  outer = (a_w + R1 + R2)(a_w + R1 - R2).
// Unlike the arccos of V3 it keeps its digits when rho_e is near 0 or 180 deg. The callers pass
// factors that are positive in doubles, so no square root sees a negative argument.
double half_angle_from_factors_deg(double inner, double outer) {
  return rad_to_deg(2.0 * std::atan2(std::sqrt(inner), std::sqrt(outer)));
}

// V3b with a_w given: the test uses the same sums as the factors, so both factor pairs are
// positive whenever the test passes.
std::optional<EngagementArc> from_center_distance(double R1, double R2, double a_w) {
  const double sum = R1 + R2;   // R1 + R2
  const double diff = R1 - R2;  // R1 - R2
  if (a_w >= sum || a_w <= std::abs(diff)) {
    return std::nullopt;
  }
  const double inner = (sum - a_w) * (a_w - diff);
  const double outer = (sum + a_w) * (a_w + diff);
  return EngagementArc{a_w, half_angle_from_factors_deg(inner, outer)};
}

// V1 and V3b with the flat depth t given. Section 5 tests t itself: a_w = R2 - t + R1 rounded
// can sit on the wrong side of a boundary that t is strictly inside. With a_w substituted the
// factors are t, 2 R2 - t, 2 (R1 + R2) - t and 2 R1 - t: positive in doubles whenever
// 0 < t < 2 min(R1, R2), and t keeps the digits that R1 + R2 - a_w loses for a shallow flat.
std::optional<EngagementArc> from_flat_depth(double R1, double R2, double t) {
  if (t >= 2.0 * std::min(R1, R2)) {
    return std::nullopt;
  }
  const double a_w = R2 - t + R1;  // a_w (V1)
  const double inner = t * (2.0 * R2 - t);
  const double outer = (2.0 * (R1 + R2) - t) * (2.0 * R1 - t);
  return EngagementArc{a_w, half_angle_from_factors_deg(inner, outer)};
}

}  // namespace

// V1, V3b
std::optional<EngagementArc> engagement_arc(
    double tool_radius_mm, double workpiece_radius_mm,
    const std::variant<CenterDistance, FlatDepth>& placement) {
  if (const auto* distance = std::get_if<CenterDistance>(&placement)) {
    return from_center_distance(tool_radius_mm, workpiece_radius_mm, distance->mm);
  }
  return from_flat_depth(tool_radius_mm, workpiece_radius_mm, std::get<FlatDepth>(placement).mm);
}

bool inside_arc(double contact_angle_deg, double half_angle_deg) {
  return std::abs(contact_angle_deg) <= half_angle_deg + kArcSlackDeg;
}

// Section 3: the entry +rho_e first, the exit -rho_e last. The integer numerator n - 1 - 2 i is
// exact and the quotient correctly rounded, so |fraction| <= 1 (no sample leaves the arc), the
// ends are +-1 exactly and sample i is the negative of sample n - 1 - i.
std::vector<double> evenly_spaced_contact_angles(double half_angle_deg, int count) {
  std::vector<double> angles;
  if (count <= 0) {
    return angles;
  }
  if (count == 1) {
    angles.push_back(0.0);
    return angles;
  }
  const double intervals = count - 1.0;  // n - 1
  angles.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    const double fraction = (intervals - 2.0 * i) / intervals;  // (n - 1 - 2 i) / (n - 1)
    angles.push_back(half_angle_deg * fraction + 0.0);          // + 0.0: no -0 in the middle
  }
  return angles;
}

}  // namespace cutcalc::domain::kinematics::detail
