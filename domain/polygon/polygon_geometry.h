#pragma once
// The hole and the construction constants of spec polygon-holes.md section 1 (P1-P5) and the
// closed-form centre-path constants of section 3 (P7, P9). Private to domain/polygon.

#include <Eigen/Core>

namespace cutcalc::domain::polygon::detail {

// n(b) = (cos b, sin b).
Eigen::Vector2d unit(double b);

// The N-gon of inscribed diameter d and every constant that depends on N and d only.
struct PolygonShape {
  int N = 4;           // faces
  int M = 3;           // rotor corners, N - 1 (P2)
  double d = 1.0;      // inscribed diameter
  double rho = 0.5;    // d / 2 (P1)
  double a = 1.0;      // side length (P1)
  double R_c = 0.0;    // circumradius (P1)
  double delta = 0.0;  // rotor turn per phase, 2 pi / (N (N - 1)) (P2)
  double q = 0.0;      // size ratio (P3)
  double r = 0.0;      // rotor corner radius (P4)
  double e = 0.0;      // eccentricity (P5)
  double A = 0.0;      // ellipse semi-axis along the vertex bisector (P7)
  double B = 0.0;      // ellipse semi-axis along the side direction (P7)
  double r_max = 0.0;  // largest distance hole centre -> centre path, A - R_c (P9)

  // alpha_j = -pi/2 + 2 pi j / N: the outward normal angle of side j.
  [[nodiscard]] double alpha(int j) const;
  // beta_j = -pi/2 + (2 j + 1) pi / N: the polar angle of vertex V_j.
  [[nodiscard]] double beta(int j) const;
  // u_j = n(alpha_j).
  [[nodiscard]] Eigen::Vector2d u(int j) const;
  // V_j = R_c n(beta_j).
  [[nodiscard]] Eigen::Vector2d vertex(int j) const;
};

// P1-P5, P7, P9 for N faces (3..12) and inscribed diameter d (> 0).
PolygonShape make_polygon_shape(int N, double d);

}  // namespace cutcalc::domain::polygon::detail
