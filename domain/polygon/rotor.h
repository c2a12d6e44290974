#pragma once
// The rotor (tool end profile) of spec polygon-holes.md section 2: M = N - 1 sharp corners and
// N - 2 flank arcs between each pair of neighbouring corners (P11, P12), and its support function
// h (P13). Rotor frame: tool axis at the origin, pose at t = 0. Private to domain/polygon.

#include <vector>

#include <Eigen/Core>

#include "domain/polygon/polygon_geometry.h"

namespace cutcalc::domain::polygon::detail {

// One flank arc (v, m) of P12: circle centre O_{v,m}, radius R_m, outward normals
// [normal_begin, normal_end] (counter-clockwise).
struct FlankArc {
  Eigen::Vector2d centre;
  double radius = 0.0;
  double normal_begin = 0.0;
  double normal_end = 0.0;
};

class Rotor {
 public:
  explicit Rotor(const PolygonShape& shape);

  // P11: theta_v = -pi/2 + 2 pi v / M.
  [[nodiscard]] double corner_angle(int v) const;
  // P11: K_v = r n(theta_v).
  [[nodiscard]] Eigen::Vector2d corner(int v) const;
  // P12: R_m = rho (1 - cos((2m+1) pi/N) / cos(pi/N)), m = 1..N-2.
  [[nodiscard]] double flank_radius(int m) const;
  // P12: arc (v, m), v = 0..M-1, m = 1..N-2.
  [[nodiscard]] FlankArc flank_arc(int v, int m) const;
  // P12: the end point of the last arc (v, N-2); equals K_{v+1} when the rotor closes.
  [[nodiscard]] Eigen::Vector2d last_arc_end(int v) const;

  // P13: h(b), the support function in the rotor frame (b: outward normal angle, any real).
  [[nodiscard]] double support(double b) const;
  // P13: the boundary point where h(b) is attained, <point, n(b)> = h(b): a corner when b is in
  // its normal cone, else the point of the flank arc with outward normal b.
  [[nodiscard]] Eigen::Vector2d support_point(double b) const;

 private:
  // b reduced to one period 2 pi / M of the M-fold symmetric rotor: b = theta_0 + turn + x with
  // turn a multiple of the period and x in [0, period); piece 0 = corner 0's cone (upper half),
  // m = 1..N-2 arc (0, m), N-1 = corner 1's cone (lower half).
  struct Piece {
    int index = 0;
    double x = 0.0;
    double turn = 0.0;
  };
  [[nodiscard]] Piece piece_of(double b) const;

  int N_;
  int M_;
  double r_;
  double delta_;
  std::vector<double> R_;                 // R_m, index m (R_[0] unused)
  std::vector<Eigen::Vector2d> centre0_;  // O_{0,m}, index m (centre0_[0] unused)
};

}  // namespace cutcalc::domain::polygon::detail
