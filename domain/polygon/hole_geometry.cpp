// sample_hole_geometry: the pieces of spec polygon-holes.md that a drawing of the hole needs,
// sampled on the unit-diameter hole (like generate_polygon_hole) and scaled to mm.

#include "domain/polygon/hole_geometry.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "domain/polygon/centre_path.h"
#include "domain/polygon/hole_outline.h"
#include "domain/polygon/polygon_geometry.h"
#include "domain/polygon/rotor.h"

namespace cutcalc::domain::polygon {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kCentrePathSamplesPerArc = 32;  // per ellipse arc (N of them per loop)
constexpr int kCornerWallSamples = 64;        // per uncut corner
constexpr int kRotorPoses = 3;
constexpr double kRotorNormalStep = kPi / 90.0;  // 2 deg of outward normal between samples
// The corner view: the rounded corner out to where it meets the sides, plus a quarter.
constexpr double kCornerViewMargin = 1.25;
// N = 3 has sharp corners (section 4): a tenth of d frames the tip.
constexpr double kSharpCornerView = 0.1;

PlanePoint to_mm(const Eigen::Vector2d& p, double d) {
  return {p.x() * d + 0.0, p.y() * d + 0.0};  // + 0.0: no -0 in the output
}

bool finite(const PlanePoint& p) { return std::isfinite(p.x_mm) && std::isfinite(p.y_mm); }

bool all_finite(const HoleGeometry& g) {
  const auto finite_list = [](const std::vector<PlanePoint>& points) {
    return std::all_of(points.begin(), points.end(), finite);
  };
  bool ok = finite_list(g.polygon) && finite_list(g.centre_path) && finite_list(g.predicted_hole) &&
            finite(g.corner_vertex) && std::isfinite(g.corner_view_radius_mm);
  for (const RotorPose& pose : g.rotor_positions) {
    ok = ok && std::isfinite(pose.phase_deg) && finite(pose.axis) && finite_list(pose.outline);
  }
  return ok;
}

}  // namespace

// P1, P7, P11-P13, P17
Result<HoleGeometry> sample_hole_geometry(const HoleGeometryParams& params) {
  const int N = params.faces;
  const double d = params.inscribed_diameter_mm;
  const detail::PolygonShape shape = detail::make_polygon_shape(N, 1.0);  // P1-P5, d = 1
  const detail::CentrePath path(shape);                                   // P6-P9
  const detail::Rotor rotor(shape);                                       // P11-P13
  HoleGeometry geometry;

  // P1: V_j.
  for (int j = 0; j < N; ++j) {
    geometry.polygon.push_back(to_mm(shape.vertex(j), d));
  }

  // P7: ellipse arc p from its phase change (theta = 0) on, so every join is a sample; the loop
  // starts at c(0) = (0, e).
  for (int p = 0; p < N; ++p) {
    for (int k = 0; k < kCentrePathSamplesPerArc; ++k) {
      const double theta = shape.delta * (static_cast<double>(k) / kCentrePathSamplesPerArc);
      geometry.centre_path.push_back(to_mm(path.point_in_phase(p, theta), d));
    }
  }

  // P14-P17: the wall of the corner at V_0 turned to every vertex (the hole is N-fold
  // symmetric); the straight middle parts of the sides join consecutive corners.
  const std::vector<Eigen::Vector2d> wall = detail::corner_wall(path, rotor, kCornerWallSamples);
  double reach = 0.0;  // farthest wall sample from V_0
  for (const Eigen::Vector2d& point : wall) {
    reach = std::max(reach, (point - shape.vertex(0)).norm());
  }
  if (N == 3) {
    geometry.predicted_hole = geometry.polygon;  // section 4: sharp corners, nothing uncut
  } else {
    for (int j = 0; j < N; ++j) {
      const Eigen::Rotation2Dd turn(2.0 * kPi * j / N);
      for (const Eigen::Vector2d& point : wall) {
        geometry.predicted_hole.push_back(to_mm(turn * point, d));
      }
    }
  }

  // Section 3: the rotor at t = i N delta / poses, axis c(t), angle phi = -t.
  for (int i = 0; i < kRotorPoses; ++i) {
    const double t = N * shape.delta * (static_cast<double>(i) / kRotorPoses);
    RotorPose pose;
    pose.phase_deg = i * 360.0 / ((N - 1.0) * kRotorPoses);  // t in degrees; a loop is 360/(N-1)
    const Eigen::Vector2d axis = path.point(t);
    pose.axis = to_mm(axis, d);
    for (const Eigen::Vector2d& point :
         detail::rotor_outline(shape, rotor, axis, -t, kRotorNormalStep)) {
      pose.outline.push_back(to_mm(point, d));
    }
    geometry.rotor_positions.push_back(std::move(pose));
  }

  geometry.corner_vertex = to_mm(shape.vertex(0), d);
  geometry.corner_view_radius_mm = (N == 3 ? kSharpCornerView : kCornerViewMargin * reach) * d;

  if (!all_finite(geometry)) {
    return make_error(ErrorCode::not_converged, "the hole geometry has a non-finite sample");
  }
  return geometry;
}

}  // namespace cutcalc::domain::polygon
