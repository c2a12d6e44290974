// machine-time.md section 4: arc centres and the end-point check of rs274ngc (interp_arc.cc).

#include "domain/machine_time/gcode_arc.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "domain/program/program_options.h"

namespace cutcalc::domain::machine_time::detail {

namespace {

double distance(const PlanePoint& a, const PlanePoint& b) {
  const double d0 = a[0] - b[0];
  const double d1 = a[1] - b[1];
  return std::sqrt(d0 * d0 + d1 * d1);
}

}  // namespace

ArcTolerance arc_tolerance(bool inch) {
  // RADIUS_TOLERANCE_INCH (0.00005 in, also the metric one converted) and
  // CENTER_ARC_RADIUS_TOLERANCE_INCH / _MM: 2 x 0.001 in x sqrt 2, 2 x 0.01 mm x sqrt 2.
  const double radius = 0.00005 * program::kMmPerInch;
  const double spiral = inch ? 2.0 * 0.001 * std::numbers::sqrt2 * program::kMmPerInch
                             : 2.0 * 0.01 * std::numbers::sqrt2;
  return {radius, spiral};
}

bool centre_fits(const PlanePoint& start, const PlanePoint& end, const PlanePoint& centre,
                 const ArcTolerance& tolerance) {
  // Plain square roots: the reader keeps numbers under 1e12, far from overflow, and hypot is
  // several times slower on a program of arcs.
  const double r_start = distance(centre, start);
  const double r_end = distance(centre, end);
  if (!(r_start >= tolerance.radius_mm) || !(r_end >= tolerance.radius_mm)) return false;
  // arc_data_ijk: a large absolute error, or a relative error over SPIRAL_RELATIVE_TOLERANCE
  // (0.1 %) that is also over the absolute tolerance.
  const double abs_err = std::fabs(r_start - r_end);
  const bool rel_over = abs_err > 0.001 * std::max(r_start, r_end);  // rel_err > 0.001
  return !(abs_err > tolerance.spiral_mm * 100.0 || (rel_over && abs_err > tolerance.spiral_mm));
}

bool centre_from_radius(const PlanePoint& start, const PlanePoint& end, double radius,
                        bool clockwise, const ArcTolerance& tolerance, PlanePoint& centre) {
  const double abs_radius = std::fabs(radius);
  if (end == start || !(abs_radius >= tolerance.radius_mm)) return false;
  const PlanePoint mid = {(start[0] + end[0]) / 2.0, (start[1] + end[1]) / 2.0};
  double half_length = std::hypot(mid[0] - end[0], mid[1] - end[1]);
  if (half_length - abs_radius > tolerance.radius_mm) return false;
  // arc_data_r: a chord a little longer than the diameter is a half circle.
  if (half_length / abs_radius > 1.0 - 1e-12) half_length = abs_radius;
  const double chord_angle = std::atan2(end[1] - start[1], end[0] - start[0]);
  const bool right_of_chord = clockwise == (radius > 0.0);
  const double theta = chord_angle + (right_of_chord ? -0.5 : 0.5) * std::numbers::pi;
  const double offset = abs_radius * std::cos(std::asin(half_length / abs_radius));
  centre = {mid[0] + offset * std::cos(theta), mid[1] + offset * std::sin(theta)};
  return std::isfinite(centre[0]) && std::isfinite(centre[1]);
}

}  // namespace cutcalc::domain::machine_time::detail
