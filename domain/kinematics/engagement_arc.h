#pragma once
// The engagement arc of the tool circle inside the workpiece circle: centre distance (V1), the
// no-contact test of section 5 and the half-angle rho_e (V3b). Private to domain/kinematics.

#include <optional>
#include <variant>
#include <vector>

#include "domain/kinematics/resultant_speeds.h"

namespace cutcalc::domain::kinematics::detail {

struct EngagementArc {
  double center_distance_mm = 0.0;  // a_w
  double half_angle_deg = 0.0;      // rho_e, 0 < rho_e < 180
};

// V1, V3b. Nothing when the circles do not cross (section 5: the flat depth is tested as given,
// before a_w is formed).
std::optional<EngagementArc> engagement_arc(
    double tool_radius_mm, double workpiece_radius_mm,
    const std::variant<CenterDistance, FlatDepth>& placement);

// Section 4 notes: |rho| <= rho_e + 1e-9 deg; the angle itself is not clamped.
bool inside_arc(double contact_angle_deg, double half_angle_deg);

// `count` contact angles evenly spaced over the whole arc in the order an edge point passes them
// (section 3): rho_i = rho_e (n - 1 - 2 i) / (n - 1), i = 0..n-1, from the entry +rho_e to the
// exit -rho_e, both ends exactly the rho_e given, the list antisymmetric and 0 in the middle for
// odd n. count = 1 gives the middle alone; count <= 0 nothing.
std::vector<double> evenly_spaced_contact_angles(double half_angle_deg, int count);

}  // namespace cutcalc::domain::kinematics::detail
