#pragma once
// The polar angle of one tooth path of a cutter orbiting inside a bore (spec roughness.md B4, B6,
// B7). Private to domain/roughness.

namespace cutcalc::domain::roughness::detail {

// Tooth path 0 of B4 as a function of delta, the tooth angle relative to the radial direction of
// the cutter centre (delta = 0 at the contact with the bore). Lengths enter only as the ratio of
// Rc and r, so huge or tiny radii cannot overflow the squares of B6.
class PlanetaryPath {
 public:
  // Rc = R - r (B1), r the cutter radius, k = eps / (m - eps) (B3).
  PlanetaryPath(double Rc, double r, double k);

  // B4: theta(delta) = k delta + atan2(r sin delta, Rc + r cos delta).
  [[nodiscard]] double theta(double delta) const;

  // B6: theta'(delta) = k + r (r + Rc cos delta) / (Rc^2 + r^2 + 2 Rc r cos delta).
  [[nodiscard]] double theta_prime(double delta) const;

  // B7: hi, the end of [0, hi] on which s theta increases; s = sign(theta'(0)).
  [[nodiscard]] double monotone_end(double s) const;

 private:
  double u_;  // Rc / max(Rc, r)
  double v_;  // r / max(Rc, r)
  double k_;  // k
};

}  // namespace cutcalc::domain::roughness::detail
