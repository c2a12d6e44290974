// Circular arcs of the fitted path: P19 (arc from a point, tangent and end); the P20 distance is
// inline in the header.

#include "domain/polygon/fitted_arc.h"

#include <Eigen/Geometry>

#include <cmath>

namespace cutcalc::domain::polygon::detail {

FittedArc FittedArc::rotated(double angle) const {
  return rotated(Eigen::Rotation2Dd(angle).toRotationMatrix(), angle);
}

FittedArc FittedArc::rotated(const Eigen::Matrix2d& rotation, double angle) const {
  FittedArc arc = *this;
  arc.start = rotation * start;
  arc.end = rotation * end;
  arc.centre = rotation * centre;
  arc.start_angle = start_angle + angle;
  return arc;
}

// P19
std::optional<FittedArc> arc_from_tangent(const Eigen::Vector2d& S, const Eigen::Vector2d& T,
                                          const Eigen::Vector2d& E) {
  const auto curvature = tangent_arc_curvature(S, T, E);
  if (!curvature) {
    return std::nullopt;
  }
  const double k = *curvature;
  const Eigen::Vector2d chord = E - S;
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
