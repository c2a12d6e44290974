#pragma once
// sin x and 1 - cos x for small |x| by their Taylor polynomials: the fit and the printed deviation
// evaluate the ellipse about a point (P7: c(psi + x) = c(psi) + sin(x) c'(psi) + (1 - cos x)
// c''(psi)) far more often than a libm call can afford. The coefficients are products, so that no
// division by a constant is turned into one.

namespace cutcalc::domain::polygon {

// Largest |x| (rad) the polynomials serve; at 0.1 their truncation is 1e-19 relative.
constexpr double kMaxSmallAngle = 0.1;

inline double sin_small(double x) {
  constexpr double c3 = -1.0 / 6.0, c5 = 1.0 / 120.0, c7 = -1.0 / 5040.0, c9 = 1.0 / 362880.0;
  const double x2 = x * x;
  return x + x * x2 * (c3 + x2 * (c5 + x2 * (c7 + x2 * c9)));
}

inline double one_minus_cos_small(double x) {
  constexpr double c2 = 1.0 / 2.0, c4 = -1.0 / 24.0, c6 = 1.0 / 720.0, c8 = -1.0 / 40320.0,
                   c10 = 1.0 / 3628800.0;
  const double x2 = x * x;
  return x2 * (c2 + x2 * (c4 + x2 * (c6 + x2 * (c8 + x2 * c10))));
}

}  // namespace cutcalc::domain::polygon
