#pragma once
// A circular arc of the fitted centre path (spec polygon-holes.md P19-P21), unrounded, in the
// units of the caller. Private to domain/polygon.

#include <algorithm>
#include <optional>

#include <Eigen/Core>

namespace cutcalc::domain::polygon::detail {

struct FittedArc {
  Eigen::Vector2d start = Eigen::Vector2d::Zero();
  Eigen::Vector2d end = Eigen::Vector2d::Zero();
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius = 0.0;
  double start_angle = 0.0;  // polar angle of start - centre
  double sweep = 0.0;        // signed turn from start to end, counter-clockwise > 0
  double length = 0.0;       // |sweep| radius

  // The point at `fraction` (0..1) of the sweep.
  [[nodiscard]] Eigen::Vector2d point_at(double fraction) const;
  // P20: distance to the arc: | |P - C| - R | inside its angular span, else to the nearer end.
  [[nodiscard]] double distance_to(const Eigen::Vector2d& P) const;
  // The arc turned by `angle` about the origin.
  [[nodiscard]] FittedArc rotated(double angle) const;
};

// P19: the arc from (S, T) to E: k = 2 (T x (E - S)) / |E - S|^2, centre = S + n(T + 90 deg) / k,
// radius 1 / |k|; its sweep is twice the signed angle from T to the chord. Empty when the chord
// or the curvature vanishes (no circle to print).
std::optional<FittedArc> arc_from_tangent(const Eigen::Vector2d& S, const Eigen::Vector2d& T,
                                          const Eigen::Vector2d& E);

// 2D cross product a x b.
inline double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Distance from P to the segment [a, b].
inline double segment_distance(const Eigen::Vector2d& P, const Eigen::Vector2d& a,
                               const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double length2 = ab.squaredNorm();
  double f = length2 > 0.0 ? (P - a).dot(ab) / length2 : 0.0;
  f = std::clamp(f, 0.0, 1.0);
  return (P - (a + f * ab)).norm();
}

}  // namespace cutcalc::domain::polygon::detail
