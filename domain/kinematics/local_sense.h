#pragma once
// Rotation sense of the workpiece (V6) and the local milling sense at a contact point (V12).
// Private to domain/kinematics.

#include "domain/common/milling_sense.h"

namespace cutcalc::domain::kinematics::detail {

// V6: s2 = +1 (workpiece turns CCW like the tool) or -1, chosen so that `milling` is the sense at
// the middle of the arc, rho = 0.
double workpiece_rotation_sign(MillingSense middle_sense, double center_distance_mm,
                               double tool_radius_mm);

// V12: the sign of v_T . v_w = omega1 omega2 R1 g(rho), taken with s2 instead of omega2.
MillingSense local_sense(double rotation_sign, double g_mm, MillingSense middle_sense);

}  // namespace cutcalc::domain::kinematics::detail
