#pragma once
// Reported angles of the resultant-speed calculation (spec resultant-speeds.md, section 3).
// Private to domain/kinematics.

#include "domain/common/numeric.h"

namespace cutcalc::domain::kinematics::detail {

// An angle from atan2, in degrees in (-180, 180]: atan2(-0, x < 0) gives -180 where the spec
// reports +180, and -0 would print as "-0.0".
inline double half_open_deg(double rad) {
  const double deg = rad_to_deg(rad);
  return deg <= -180.0 ? 180.0 : deg + 0.0;
}

}  // namespace cutcalc::domain::kinematics::detail
