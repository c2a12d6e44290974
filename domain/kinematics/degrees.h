#pragma once
// Degree and radian conversions of the resultant-speed calculation (spec resultant-speeds.md,
// section 3). Private to domain/kinematics.

namespace cutcalc::domain::kinematics::detail {

// The spec fixes these two doubles (the reference generator multiplies by them), so that angles
// copied from a response, such as rho_e, round-trip to the same radians the server used.
inline constexpr double kRadPerDeg = 0.017453292519943295;  // pi / 180
inline constexpr double kDegPerRad = 57.29577951308232;     // 180 / pi

// An angle from atan2, in degrees in (-180, 180]: atan2(-0, x < 0) gives -180 where the spec
// reports +180, and -0 would print as "-0.0".
inline double half_open_deg(double rad) {
  const double deg = rad * kDegPerRad;
  return deg <= -180.0 ? 180.0 : deg + 0.0;
}

}  // namespace cutcalc::domain::kinematics::detail
