// Contour functions e(y), f(y) of section 3 (spec entry-and-main-time.md).

#include "domain/entry/contour_shape.h"

#include <cmath>

#include "domain/common/numeric.h"

namespace cutcalc::domain::entry::detail {

namespace {

// Sag of a circle of radius R at lateral distance y from its axis: R - sqrt(R^2 - y^2), written
// as y^2 / (R + sqrt(R^2 - y^2)) so that a large R with a small y keeps its digits (section 11:
// R -> infinity must tend to the straight edge).
double arc_sag_mm(double radius_mm, double y_mm) {
  return (y_mm * y_mm) / (radius_mm + sqrt_diff_sq(radius_mm, y_mm));
}

// Depth of a concave notch at y: sqrt(R^2 - y^2) - c0 with c0 = sqrt(R^2 - h^2), written as
// (h - |y|)(h + |y|) / (sqrt(R^2 - y^2) + c0) so that it is exactly 0 at the corners y = +-h.
double notch_depth_mm(double radius_mm, double half_width, double y_mm) {
  const double y_abs = std::abs(y_mm);
  const double numerator = (half_width - y_abs) * (half_width + y_abs);
  const double denominator = sqrt_diff_sq(radius_mm, y_mm) + sqrt_diff_sq(radius_mm, half_width);
  // Both roots vanish only at a corner of a half-circle notch (h = R, |y| = h), where the depth is
  // 0.
  return denominator > 0.0 ? numerator / denominator : 0.0;
}

}  // namespace

EdgeTrig edge_trig(double angle_deg) {
  if (angle_deg == 90.0) {
    return EdgeTrig{};
  }
  const double alpha = deg_to_rad(angle_deg);  // alpha
  return EdgeTrig{std::sin(alpha), std::cos(alpha), cot_deg(angle_deg)};
}

// E3
double half_width_mm(const Contour& contour) { return part_width_mm(contour) / 2.0; }

double entry_edge_x_mm(const Contour& contour, double y_mm) {
  const double h = half_width_mm(contour);  // h
  switch (contour.kind) {
    case ContourKind::straight:
      return (y_mm + h) * edge_trig(contour.angle_deg).cot_alpha;
    case ContourKind::convex_arc:
      return arc_sag_mm(contour.radius_mm, y_mm);
    case ContourKind::concave_arc:
      return notch_depth_mm(contour.radius_mm, h, y_mm);
    case ContourKind::wall:
      // The API never sends a wall as an entry; its face x = 0 reads as a perpendicular edge.
      return 0.0;
  }
  return 0.0;
}

double exit_edge_x_mm(const Contour& contour, double y_mm) {
  const double h = half_width_mm(contour);  // h_x
  switch (contour.kind) {
    case ContourKind::straight:
      return (y_mm + h) * edge_trig(contour.angle_deg).cot_alpha;
    case ContourKind::convex_arc:
      // The exit arc is the entry arc mirrored across x = 0: its apex is the most downstream point.
      return -arc_sag_mm(contour.radius_mm, y_mm);
    case ContourKind::concave_arc:
      return -notch_depth_mm(contour.radius_mm, h, y_mm);
    case ContourKind::wall:
      return 0.0;
  }
  return 0.0;
}

// Section 3
double frame_y_mm(const Contour& contour, double y_mm) {
  if (contour.kind == ContourKind::straight || contour.kind == ContourKind::wall) {
    return half_width_mm(contour) + y_mm;
  }
  return y_mm;
}

}  // namespace cutcalc::domain::entry::detail
