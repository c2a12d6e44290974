#pragma once
// Small numeric helpers shared by the calculation families. Angles inside the math are radians.

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cutcalc::domain {

// Degrees to radians and back as x * (pi/180) and x * (180/pi) with the doubles the specs fix
// (resultant-speeds.md section 3, roughness.md "Common rules"): the reference generator multiplies
// by them, so angles copied from a response round-trip to the radians the server used.
inline constexpr double kRadPerDeg = 0.017453292519943295;  // pi / 180
inline constexpr double kDegPerRad = 57.29577951308232;     // 180 / pi
static_assert(kRadPerDeg == std::numbers::pi / 180.0 && kDegPerRad == 180.0 / std::numbers::pi);

inline double deg_to_rad(double deg) { return deg * kRadPerDeg; }
inline double rad_to_deg(double rad) { return rad * kDegPerRad; }
// Radians to degrees as (x * 180) / pi, two roundings: the lathe-flat family's C angles
// (lathe-flat.md F7) have always been computed so. It differs from rad_to_deg in the last bit for
// some angles, so the two are not interchangeable without changing printed results.
inline double rad_times_180_over_pi(double rad) { return rad * 180.0 / std::numbers::pi; }
// Degrees to radians as (x * pi) / 180, two roundings: the grooving cycle's phi1 (grooving-cycle.md
// K22) has always been computed so; like rad_times_180_over_pi it can differ from deg_to_rad in the
// last bit, and the side chip thickness is answered to the last digit.
inline double deg_times_pi_over_180(double deg) { return deg * std::numbers::pi / 180.0; }

// A count of passes, layers or revolutions for the quotient q = what is to be cut / what one of
// them cuts, at least 1: ceil(q - 1e-9) (entry-and-main-time.md E24, polygon-holes.md P22,
// lathe-flat.md F17, grooving-cycle.md K7), so that a quotient rounded just above a whole number
// (0.07 / 0.01 = 7.000000000000001) is not one more. A double: the caller checks it against its cap
// before it converts it to an integer.
inline double ceil_count(double q) { return std::max(1.0, std::ceil(q - 1e-9)); }

// sqrt(p^2 - q^2) evaluated as sqrt((p - q)(p + q)) so that tangency (p = q) is exactly 0 and
// nearly equal arguments keep their digits; tiny negative products from rounding clamp to 0.
inline double sqrt_diff_sq(double p, double q) {
  const double product = (p - q) * (p + q);
  return product > 0.0 ? std::sqrt(product) : 0.0;
}

// cot(alpha) for alpha in degrees with cot(90) = 0 exactly (cos(pi/2) is not 0 in doubles).
inline double cot_deg(double alpha_deg) {
  if (alpha_deg == 90.0) {
    return 0.0;
  }
  const double alpha = deg_to_rad(alpha_deg);
  return std::cos(alpha) / std::sin(alpha);
}

}  // namespace cutcalc::domain
