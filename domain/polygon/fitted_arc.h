#pragma once
// A circular arc of the fitted centre path (spec polygon-holes.md P19-P21), unrounded, in the
// units of the caller. Private to domain/polygon.

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
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

  // The point at `fraction` (0..1) of the sweep. Inline: the overcut prediction samples every
  // block with it.
  [[nodiscard]] Eigen::Vector2d point_at(double fraction) const {
    const double angle = start_angle + fraction * sweep;
    return centre + radius * Eigen::Vector2d(std::cos(angle), std::sin(angle));  // unit(angle)
  }
  // P20: distance to the arc: | |P - C| - R | inside its angular span, else to the nearer end.
  // Defined below, inline: the arc fit calls it twice for every path sample.
  [[nodiscard]] double distance_to(const Eigen::Vector2d& P) const;
  // distance_to(P) before its square root: | sqrt(squared) - radius | where `radial`, else
  // sqrt(squared). A caller after the smaller of two distances can often rule one out from the
  // squares alone.
  struct DistanceParts {
    bool radial = false;
    double squared = 0.0;
    [[nodiscard]] double distance(double radius) const {
      return radial ? std::abs(std::sqrt(squared) - radius) : std::sqrt(squared);
    }
  };
  [[nodiscard]] DistanceParts distance_parts(const Eigen::Vector2d& P) const;
  // The arc turned by `angle` about the origin.
  [[nodiscard]] FittedArc rotated(double angle) const;
  // The same with the rotation matrix of `angle` given (Eigen::Rotation2Dd(angle) computes it
  // for every vector it turns): for many arcs turned alike.
  [[nodiscard]] FittedArc rotated(const Eigen::Matrix2d& rotation, double angle) const;
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

// The square of the distance from P to the segment from a along ab (= b - a, with
// length2 = |ab|^2): segment_distance is its square root. Callers that measure many points
// against one segment compute ab and length2 once; callers that compare distances compare these
// (the square root is monotone) and take roots only where they must.
inline double segment_distance_squared(const Eigen::Vector2d& P, const Eigen::Vector2d& a,
                                       const Eigen::Vector2d& ab, double length2) {
  const Eigen::Vector2d ap = P - a;
  if (length2 > 0.0 && length2 < std::numeric_limits<double>::infinity()) {
    // f = clamp((P - a).ab / length2, 0, 1): where the clamp decides f, the point of the
    // segment is a end exactly (a + 0 ab = a, a + 1 ab = a + ab) and the division is not needed.
    const double dot = ap.dot(ab);
    if (dot <= 0.0) {
      return ap.squaredNorm();
    }
    if (dot >= length2) {
      return (P - (a + ab)).squaredNorm();
    }
    return (P - (a + (dot / length2) * ab)).squaredNorm();  // dot < length2: f <= 1
  }
  double f = length2 > 0.0 ? ap.dot(ab) / length2 : 0.0;
  f = std::clamp(f, 0.0, 1.0);
  return (P - (a + f * ab)).squaredNorm();
}

// Distance from P to the segment [a, b].
inline double segment_distance(const Eigen::Vector2d& P, const Eigen::Vector2d& a,
                               const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  return std::sqrt(segment_distance_squared(P, a, ab, ab.squaredNorm()));
}

// P19's signed curvature k = 2 (T x (E - S)) / |E - S|^2 of the arc from (S, T) to E; empty when
// the chord or the curvature vanishes. arc_from_tangent decides with it, so a caller that only
// needs to know whether the arc exists gets the same answer without the arc's angles.
inline std::optional<double> tangent_arc_curvature(const Eigen::Vector2d& S,
                                                   const Eigen::Vector2d& T,
                                                   const Eigen::Vector2d& E) {
  const Eigen::Vector2d chord = E - S;
  const double chord2 = chord.squaredNorm();
  const double k = 2.0 * cross(T, chord) / chord2;
  if (!(chord2 > 0.0) || !(k != 0.0) || !std::isfinite(k)) {
    return std::nullopt;
  }
  return k;
}

// P20
inline FittedArc::DistanceParts FittedArc::distance_parts(const Eigen::Vector2d& P) const {
  const Eigen::Vector2d v = P - centre;
  const Eigen::Vector2d s = start - centre;
  bool inside = false;
  if (std::abs(sweep) <= std::numbers::pi) {
    // The span is a wedge of at most a half turn: two cross products decide.
    const double sense = sweep < 0.0 ? -1.0 : 1.0;
    inside = sense * cross(s, v) >= 0.0 && sense * cross(v, end - centre) >= 0.0;
  } else {
    // Angle from the start direction to v, measured in the arc's own sense, in [0, 2 pi).
    double angle = std::atan2(cross(s, v), s.dot(v));
    if (sweep < 0.0) {
      angle = -angle;
    }
    if (angle < 0.0) {
      angle += 2.0 * std::numbers::pi;
    }
    inside = angle <= std::abs(sweep);
  }
  if (inside) {
    return {true, v.squaredNorm()};
  }
  // The nearer end by its squared distance: one square root, the same value (sqrt is monotone).
  return {false, std::min((P - start).squaredNorm(), (P - end).squaredNorm())};
}

inline double FittedArc::distance_to(const Eigen::Vector2d& P) const {
  return distance_parts(P).distance(radius);
}

}  // namespace cutcalc::domain::polygon::detail
