// V6 and V12 of spec resultant-speeds.md.

#include "domain/kinematics/local_sense.h"

namespace cutcalc::domain::kinematics::detail {

// V6. Down-milling means the surfaces move the same way (v_T . v_w > 0). At rho = 0,
// g(0) = R1 - a_w is negative for the usual a_w > R1, so equal rotation senses make the surfaces
// meet (up); with the workpiece axis inside the tool circle (a_w < R1) it is the other way round.
// a_w = R1 puts the middle point on the workpiece axis (g(0) = 0); the sense there is taken as the
// limit rho -> 0, where g > 0, hence the "<=" (inferred in the spec).
double workpiece_rotation_sign(MillingSense middle_sense, double center_distance_mm,
                               double tool_radius_mm) {
  const bool down = middle_sense == MillingSense::down;
  const bool axis_inside = center_distance_mm <= tool_radius_mm;  // a_w <= R1
  return down == axis_inside ? 1.0 : -1.0;                        // s2
}

// V12. Using s2 rather than omega2 keeps the sense defined for a still workpiece (n2 = 0): it is
// the sense an arbitrarily slow rotation in the requested direction would give. Where g = 0 the
// surfaces are perpendicular and the request's own sense is reported.
MillingSense local_sense(double rotation_sign, double g_mm, MillingSense middle_sense) {
  const double s2_g = rotation_sign * g_mm;  // s2 g(rho)
  if (s2_g > 0.0) {
    return MillingSense::down;
  }
  if (s2_g < 0.0) {
    return MillingSense::up;
  }
  return middle_sense;
}

}  // namespace cutcalc::domain::kinematics::detail
