// P11-P13 of spec polygon-holes.md: rotor corners, flank arcs and the support function.

#include "domain/polygon/rotor.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cutcalc::domain::polygon::detail {

namespace {

Eigen::Vector2d rotate(const Eigen::Vector2d& x, double angle) {
  return Eigen::Rotation2Dd(angle) * x;
}

}  // namespace

Rotor::Rotor(const PolygonShape& shape)
    : N_(shape.N),
      M_(shape.M),
      r_(shape.r),
      delta_(shape.delta),
      R_(static_cast<std::size_t>(shape.N - 1), 0.0),
      centre0_(static_cast<std::size_t>(shape.N - 1), Eigen::Vector2d::Zero()) {
  constexpr double pi = std::numbers::pi;
  // P12: R_m, m = 1..N-2.
  for (int m = 1; m <= N_ - 2; ++m) {
    R_[m] = shape.rho * (1.0 - std::cos((2.0 * m + 1.0) * pi / N_) / std::cos(pi / N_));
  }
  // P12: O_{0,1} = K_0 - R_1 n(theta_0 + delta), O_{0,m+1} = O_{0,m} + (R_m - R_{m+1}) n(...).
  const double theta_0 = corner_angle(0);
  centre0_[1] = corner(0) - R_[1] * unit(theta_0 + delta_);
  for (int m = 1; m + 1 <= N_ - 2; ++m) {
    centre0_[m + 1] = centre0_[m] + (R_[m] - R_[m + 1]) * unit(theta_0 + (m + 1) * delta_);
  }
}

// P11
double Rotor::corner_angle(int v) const {
  return -0.5 * std::numbers::pi + 2.0 * std::numbers::pi * v / M_;
}

// P11
Eigen::Vector2d Rotor::corner(int v) const { return r_ * unit(corner_angle(v)); }

// P12
double Rotor::flank_radius(int m) const { return R_[m]; }

// P12: arc (v, m) is arc (0, m) turned by 2 pi v / M (the rotor is M-fold symmetric).
FlankArc Rotor::flank_arc(int v, int m) const {
  const double turn = 2.0 * std::numbers::pi * v / M_;
  const double theta_v = corner_angle(v);
  return FlankArc{rotate(centre0_[m], turn), R_[m], theta_v + m * delta_,
                  theta_v + (m + 1) * delta_};
}

// P12
Eigen::Vector2d Rotor::last_arc_end(int v) const {
  const FlankArc arc = flank_arc(v, N_ - 2);
  return arc.centre + arc.radius * unit(arc.normal_end);
}

// P13. x = b - theta_0 reduced to one period 2 pi / M = N delta of the M-fold symmetric rotor:
// [0, delta) is the upper half of corner 0's normal cone, [m delta, (m+1) delta) arc (0, m),
// [(N-1) delta, N delta) the lower half of corner 1's cone. n(theta_0 + x) = (sin x, -cos x).
Rotor::Piece Rotor::piece_of(double b) const {
  const double period = 2.0 * std::numbers::pi / M_;
  double x = std::fmod(b + 0.5 * std::numbers::pi, period);
  if (x < 0.0) {
    x += period;
  }
  const int piece = std::clamp(static_cast<int>(x / delta_), 0, N_ - 1);
  return Piece{piece, x, b + 0.5 * std::numbers::pi - x};
}

double Rotor::support(double b) const {
  const double period = 2.0 * std::numbers::pi / M_;
  const Piece piece = piece_of(b);
  const double x = piece.x;
  if (piece.index == 0) {
    return r_ * std::cos(x);
  }
  if (piece.index == N_ - 1) {
    return r_ * std::cos(period - x);
  }
  const Eigen::Vector2d& O = centre0_[piece.index];
  return O.x() * std::sin(x) - O.y() * std::cos(x) + R_[piece.index];
}

// P13: the same pieces as support(), as points; the reduced pose turned back by `turn`.
Eigen::Vector2d Rotor::support_point(double b) const {
  const Piece piece = piece_of(b);
  Eigen::Vector2d point;
  if (piece.index == 0) {
    point = corner(0);
  } else if (piece.index == N_ - 1) {
    point = corner(1);
  } else {
    point = centre0_[piece.index] + R_[piece.index] * unit(corner_angle(0) + piece.x);
  }
  return rotate(point, piece.turn);
}

}  // namespace cutcalc::domain::polygon::detail
