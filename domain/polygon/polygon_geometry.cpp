// P1-P5, P7 and P9 of spec polygon-holes.md: the N-gon and the construction constants.

#include "domain/polygon/polygon_geometry.h"

#include <cmath>
#include <numbers>

namespace cutcalc::domain::polygon::detail {

Eigen::Vector2d unit(double b) { return {std::cos(b), std::sin(b)}; }

double PolygonShape::alpha(int j) const {
  return -0.5 * std::numbers::pi + 2.0 * std::numbers::pi * j / N;
}

double PolygonShape::beta(int j) const {
  return -0.5 * std::numbers::pi + (2.0 * j + 1.0) * std::numbers::pi / N;
}

Eigen::Vector2d PolygonShape::u(int j) const { return unit(alpha(j)); }

Eigen::Vector2d PolygonShape::vertex(int j) const { return R_c * unit(beta(j)); }

PolygonShape make_polygon_shape(int N, double d) {
  constexpr double pi = std::numbers::pi;
  PolygonShape shape;
  shape.N = N;
  shape.M = N - 1;                           // P2
  shape.d = d;                               // P1
  shape.rho = 0.5 * d;                       // P1
  shape.a = d * std::tan(pi / N);            // P1
  shape.R_c = shape.rho / std::cos(pi / N);  // P1
  shape.delta = 2.0 * pi / (N * (N - 1.0));  // P2
  const double ratio = std::sin(0.5 * shape.delta) / std::sin(pi / N);
  shape.q = ratio * ratio;                                             // P3
  shape.r = shape.rho / (1.0 - shape.q);                               // P4
  shape.e = shape.r * shape.q;                                         // P5
  shape.A = shape.r * std::cos(0.5 * shape.delta) / std::cos(pi / N);  // P7
  shape.B = shape.r * ratio;                                           // P7: r sqrt(q)
  shape.r_max = shape.A - shape.R_c;                                   // P9
  return shape;
}

}  // namespace cutcalc::domain::polygon::detail
