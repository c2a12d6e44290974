// Circular arcs of the fitted path: P19 (arc from a point, tangent and end) and the P20 distance.

#include "domain/polygon/fitted_arc.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "domain/polygon/polygon_geometry.h"

namespace cutcalc::domain::polygon::detail {

Eigen::Vector2d FittedArc::point_at(double fraction) const {
  return centre + radius * unit(start_angle + fraction * sweep);
}

// P20
double FittedArc::distance_to(const Eigen::Vector2d& P) const {
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
    return std::abs(v.norm() - radius);
  }
  return std::min((P - start).norm(), (P - end).norm());
}

FittedArc FittedArc::rotated(double angle) const {
  const Eigen::Rotation2Dd turn(angle);
  FittedArc arc = *this;
  arc.start = turn * start;
  arc.end = turn * end;
  arc.centre = turn * centre;
  arc.start_angle = start_angle + angle;
  return arc;
}

// P19
std::optional<FittedArc> arc_from_tangent(const Eigen::Vector2d& S, const Eigen::Vector2d& T,
                                          const Eigen::Vector2d& E) {
  const Eigen::Vector2d chord = E - S;
  const double chord2 = chord.squaredNorm();
  const double k = 2.0 * cross(T, chord) / chord2;  // signed curvature
  if (!(chord2 > 0.0) || !(k != 0.0) || !std::isfinite(k)) {
    return std::nullopt;
  }
  FittedArc arc;
  arc.start = S;
  arc.end = E;
  arc.centre = S + Eigen::Vector2d(-T.y(), T.x()) / k;
  arc.radius = 1.0 / std::abs(k);
  const Eigen::Vector2d from_centre = S - arc.centre;
  arc.start_angle = std::atan2(from_centre.y(), from_centre.x());
  arc.sweep = 2.0 * std::atan2(cross(T, chord), T.dot(chord));
  arc.length = std::abs(arc.sweep) * arc.radius;
  return arc;
}

}  // namespace cutcalc::domain::polygon::detail
