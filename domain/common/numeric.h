#pragma once
// Small numeric helpers shared by the calculation families. Angles inside the math are radians.

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cutcalc::domain {

inline double deg_to_rad(double deg) { return deg * std::numbers::pi / 180.0; }
inline double rad_to_deg(double rad) { return rad * 180.0 / std::numbers::pi; }

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
