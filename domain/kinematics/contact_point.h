#pragma once
// Speeds at one contact point of the engagement arc (V2, V4, V5, V7-V14). Private to
// domain/kinematics.

#include "domain/common/milling_sense.h"
#include "domain/kinematics/resultant_speeds.h"

namespace cutcalc::domain::kinematics::detail {

// What every contact point of one request shares, in mm and mm/min.
struct Kinematics {
  double tool_radius_mm = 0.0;                   // R1
  double center_distance_mm = 0.0;               // a_w
  double omega1 = 0.0;                           // omega1 = 2 pi n1, rad/min, > 0 (tool turns CCW)
  double omega2 = 0.0;                           // omega2 = s2 2 pi n2, rad/min, signed
  double rotation_sign = 1.0;                    // s2 (V6)
  double tool_feed_mm_per_min = 0.0;             // v_s1, along X
  double cos_lambda = 1.0;                       // cos(lambda)
  double sin_lambda = 0.0;                       // sin(lambda)
  MillingSense middle_sense = MillingSense::up;  // `milling`: the sense at rho = 0
};

// V6 and the request's constants; a_w from V1 or as given.
Kinematics make_kinematics(const ResultantSpeedsParams& params, double center_distance_mm);

// V2, V4, V5, V7-V14 at the contact angle rho (degrees, used as given).
ContactPointSpeeds contact_point_speeds(const Kinematics& kinematics, double contact_angle_deg);

}  // namespace cutcalc::domain::kinematics::detail
