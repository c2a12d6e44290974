// B4, B6, B7 of spec roughness.md (paper 001).

#include "domain/roughness/planetary_path.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cutcalc::domain::roughness::detail {

PlanetaryPath::PlanetaryPath(double Rc, double r, double k)
    : u_(Rc / std::max(Rc, r)), v_(r / std::max(Rc, r)), k_(k) {}

// B4
double PlanetaryPath::theta(double delta) const {
  return k_ * delta + std::atan2(v_ * std::sin(delta), u_ + v_ * std::cos(delta));
}

// B6
double PlanetaryPath::theta_prime(double delta) const {
  const double c = std::cos(delta);
  return k_ + v_ * (v_ + u_ * c) / (u_ * u_ + v_ * v_ + 2.0 * u_ * v_ * c);
}

// B7
double PlanetaryPath::monotone_end(double s) const {
  constexpr double kQuarterTurn = 0.5 * std::numbers::pi;
  // theta'(pi/2) with cos(pi/2) = 0 exactly: std::cos of the double nearest pi/2 is 6e-17.
  const double theta_prime_quarter = k_ + v_ * v_ / (u_ * u_ + v_ * v_);
  if (s * theta_prime_quarter > 0.0) {
    return kQuarterTurn;
  }
  // delta_m, the zero of theta': B6 is linear-fractional in cos delta. The clamp absorbs rounding
  // and, with the negated comparison, a degenerate 0/0.
  double cos_delta_m = -(k_ * (u_ * u_ + v_ * v_) + v_ * v_) / (u_ * v_ * (2.0 * k_ + 1.0));
  if (!(cos_delta_m >= -1.0)) {
    cos_delta_m = -1.0;
  }
  cos_delta_m = std::min(cos_delta_m, 1.0);
  return std::acos(cos_delta_m);
}

}  // namespace cutcalc::domain::roughness::detail
