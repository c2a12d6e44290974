#include "domain/machine_time/segment_builder.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace cutcalc::domain::machine_time {
namespace {

Vec3 xyz(const AxisVector& p) { return {p[0], p[1], p[2]}; }

// What the axes allow along a displacement (M4): the velocity and acceleration at which the
// slowest axis is just at its limit; the length is the xyz length, or the rotary length for a
// rotary-only move (LinuxCNC counts those in degrees).
struct AxisCaps {
  double velocity = std::numeric_limits<double>::infinity();
  double acceleration = std::numeric_limits<double>::infinity();
  double velocity_time = 0.0;      // max |d_i| / v_i
  double acceleration_time = 0.0;  // max |d_i| / a_i
};

AxisCaps axis_caps(const AxisVector& displacement, double length, const Machine& machine) {
  AxisCaps caps;
  for (std::size_t i = 0; i < kAxisCount; ++i) {
    const double d = std::fabs(displacement[i]);
    const auto& limits = machine.axes[i];
    if (d == 0.0 || !limits) {
      continue;
    }
    caps.velocity_time = std::max(caps.velocity_time, d / limits->max_velocity_per_s);
    caps.acceleration_time = std::max(caps.acceleration_time, d / limits->max_acceleration_per_s2);
  }
  if (caps.velocity_time > 0.0) {
    caps.velocity = length / caps.velocity_time;
  }
  if (caps.acceleration_time > 0.0) {
    caps.acceleration = length / caps.acceleration_time;
  }
  return caps;
}

// Spindle speed at radius r (mm) under constant surface speed, clamped (M1, G96).
double css_rpm(const Feed& feed, double radius_mm) {
  const double r = std::max(std::fabs(radius_mm), 1e-3);
  double rpm = feed.surface_speed_m_per_min * 1000.0 / (2.0 * std::numbers::pi * r);
  if (feed.max_spindle_rpm > 0.0) {
    rpm = std::min(rpm, feed.max_spindle_rpm);
  }
  return rpm;
}

// The feed velocity the block asks for, units/s: F/min, length * F for inverse time (G93), F * n
// per revolution (G95; under G96 the mean over the move of a speed that follows the radius X).
double requested_velocity(const Move& move, double length) {
  const Feed& feed = move.feed;
  switch (feed.mode) {
    case FeedMode::units_per_min:
      return feed.value / 60.0;
    case FeedMode::inverse_time:
      return length * feed.value / 60.0;
    case FeedMode::per_revolution:
      break;
  }
  if (feed.surface_speed_m_per_min <= 0.0) {
    return feed.value * feed.spindle_rpm / 60.0;
  }
  // T = integral ds / (F n(r(s)) / 60), Simpson's rule over the straight X change (an arc's X
  // is taken along its chord: the lathe programs cutcalc writes turn in straight lines).
  constexpr int kIntervals = 32;
  const double x0 = move.start[0];
  const double x1 = move.end[0];
  double sum = 0.0;
  for (int k = 0; k <= kIntervals; ++k) {
    const double u = static_cast<double>(k) / kIntervals;
    const double weight = (k == 0 || k == kIntervals) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
    sum += weight / css_rpm(feed, x0 + (x1 - x0) * u);
  }
  const double mean_inverse_rpm = sum / (3.0 * kIntervals);
  return feed.value / (60.0 * mean_inverse_rpm);
}

struct PlaneAxes {
  std::size_t first;
  std::size_t second;
  std::size_t normal;
};

PlaneAxes plane_axes(Plane plane) {
  switch (plane) {
    case Plane::xy:
      return {0, 1, 2};
    case Plane::xz:
      return {2, 0, 1};  // G18 is (Z, X) about +Y
    case Plane::yz:
      return {1, 2, 0};
  }
  return {0, 1, 2};
}

Vec3 axis_unit(std::size_t axis) {
  Vec3 v;
  (axis == 0 ? v.x : axis == 1 ? v.y : v.z) = 1.0;
  return v;
}

double component(Vec3 v, std::size_t axis) { return axis == 0 ? v.x : axis == 1 ? v.y : v.z; }

void set_component(Vec3& v, std::size_t axis, double value) {
  (axis == 0 ? v.x : axis == 1 ? v.y : v.z) = value;
}

AxisVector displacement(const Move& move) {
  AxisVector d{};
  for (std::size_t i = 0; i < kAxisCount; ++i) {
    d[i] = move.end[i] - move.start[i];
  }
  return d;
}

bool moves_rotary(const AxisVector& d) { return d[3] != 0.0 || d[4] != 0.0 || d[5] != 0.0; }

void set_feeds(Segment& segment, const Move& move, const AxisCaps& caps, double length) {
  if (move.kind == MoveKind::rapid) {
    segment.rapid = true;
    segment.reqvel = caps.velocity;
    segment.maxvel = caps.velocity;
    segment.feed_cap = 0.0;
    segment.nominal_velocity = caps.velocity;
    return;
  }
  segment.synced = move.feed.mode == FeedMode::per_revolution;
  segment.feed_cap = requested_velocity(move, length);
  segment.reqvel = std::min(segment.feed_cap, caps.velocity);
  segment.maxvel = caps.velocity;
  segment.nominal_velocity = segment.reqvel;
  if (segment.reqvel < segment.feed_cap * (1.0 - 1e-12)) {
    segment.limit = Limit::axis_velocity;
    segment.feed_capped = true;
  }
}

std::optional<Segment> build_line(const Move& move, const Machine& machine) {
  const AxisVector d = displacement(move);
  const Vec3 delta = xyz(move.end) - xyz(move.start);
  double length = norm(delta);
  Segment segment;
  segment.shape = Shape::line;
  segment.rotary = moves_rotary(d);
  if (length <= kPositionEpsilon) {
    length = std::sqrt(d[3] * d[3] + d[4] * d[4] + d[5] * d[5]);
    segment.pure_rotary = true;
  }
  if (length <= kPositionEpsilon) {
    return std::nullopt;
  }
  const AxisCaps caps = axis_caps(d, length, machine);
  segment.target = length;
  segment.nominal_length = length;
  segment.maxaccel = caps.acceleration;
  set_feeds(segment, move, caps, length);
  segment.start_tangent = unit(delta);
  segment.end_tangent = segment.start_tangent;
  segment.end_point = xyz(move.end);
  return segment;
}

std::optional<Segment> build_arc(const Move& move, const Machine& machine) {
  const PlaneAxes axes = plane_axes(move.arc.plane);
  const Vec3 start = xyz(move.start);
  const Vec3 end = xyz(move.end);
  const Vec3 plane_normal = axis_unit(axes.normal);
  Vec3 centre = start;
  set_component(centre, axes.first, move.arc.centre[0]);
  set_component(centre, axes.second, move.arc.centre[1]);
  const Vec3 turn_axis = move.arc.clockwise ? -1.0 * plane_normal : plane_normal;

  Vec3 end_in_plane = end;
  set_component(end_in_plane, axes.normal, component(start, axes.normal));
  const Vec3 r_start = start - centre;
  const Vec3 r_end = end_in_plane - centre;
  const double radius = norm(r_start);
  const double end_radius = norm(r_end);
  if (radius <= kPositionEpsilon) {
    return std::nullopt;
  }
  double angle = std::atan2(dot(turn_axis, cross(r_start, r_end)), dot(r_start, r_end));
  if (angle <= 1e-12) {
    angle += 2.0 * std::numbers::pi;
  }
  angle += 2.0 * std::numbers::pi * move.arc.extra_turns;

  const double spiral = end_radius - radius;
  const double height = component(end - start, axes.normal);  // signed, along +normal axis
  const double min_radius = std::min(radius, end_radius);
  const double circular_length = min_radius * angle;
  // sqrt of the squares rather than std::hypot (several times slower, and these are far from
  // overflow: lengths are below 1e6 mm).
  const double spiral_length = std::sqrt(circular_length * circular_length + spiral * spiral);
  const double length = std::sqrt(spiral_length * spiral_length + height * height);
  if (length <= kPositionEpsilon) {
    return std::nullopt;
  }

  // ARC_FEED: the planar axes' limits, the radial cap sqrt(a_n r) (M5), and the straight-line
  // caps of the other axes (a helix's normal axis, rotary axes).
  const auto planar = [&](std::size_t axis, bool velocity) {
    const auto& limits = machine.axes[axis];
    if (!limits) {
      return std::numeric_limits<double>::infinity();
    }
    return velocity ? limits->max_velocity_per_s : limits->max_acceleration_per_s2;
  };
  const double v_axes = std::min(planar(axes.first, true), planar(axes.second, true));
  const double a_axes = std::min(planar(axes.first, false), planar(axes.second, false));
  const double dr = spiral / angle;
  const double effective_for_canon = std::sqrt(dr * dr + min_radius * min_radius);
  const double v_radial = std::sqrt(a_axes * kNormalAccelRatio * effective_for_canon);
  const double v_planar = std::min(v_radial, v_axes);
  const AxisVector d = displacement(move);
  const AxisCaps straight = axis_caps(d, length, machine);
  const double t_velocity = std::max(straight.velocity_time, spiral_length / v_planar);
  const double t_acceleration = std::max(straight.acceleration_time, spiral_length / a_axes);
  AxisCaps caps;
  caps.velocity = length / t_velocity;
  caps.acceleration = length / t_acceleration;

  Segment segment;
  segment.shape = Shape::arc;
  segment.rotary = moves_rotary(d);
  segment.target = length;
  segment.nominal_length = length;
  segment.maxaccel = caps.acceleration;
  set_feeds(segment, move, caps, length);
  if (v_radial < v_axes && v_radial < segment.feed_cap) {
    segment.limit = Limit::arc;
  }
  // M1 caps the feed by the axes' velocities only, not by the arc's normal acceleration.
  const double v_axes_only = length / std::max(straight.velocity_time, spiral_length / v_axes);
  segment.nominal_velocity =
      move.kind == MoveKind::rapid ? v_axes_only : std::min(segment.feed_cap, v_axes_only);
  const double rise_per_radian = height / angle;
  const Vec3 along_axis = rise_per_radian * plane_normal;
  segment.start_tangent = unit(radius * unit(cross(turn_axis, r_start)) + along_axis);
  segment.end_tangent = unit(end_radius * unit(cross(turn_axis, r_end)) + along_axis);
  segment.end_point = end;
  segment.normal = turn_axis;
  segment.arc_radius = radius;
  // pmCircleEffectiveMinRadius: a spiral's and a helix's curvature radius is larger.
  const double tp_dr = spiral / angle;
  const double n_inner = tp_dr * tp_dr + radius * radius;
  const double r_spiral = std::sqrt(n_inner * n_inner * n_inner) / (n_inner + tp_dr * tp_dr);
  segment.effective_radius = height * height / r_spiral + r_spiral;
  segment.effective_radius = std::max(segment.effective_radius, kDoubleFuzz);
  return segment;
}

}  // namespace

std::optional<Segment> build_segment(const Move& move, const Machine& machine) {
  std::optional<Segment> segment =
      move.kind == MoveKind::arc ? build_arc(move, machine) : build_line(move, machine);
  if (!segment) {
    return segment;
  }
  segment->line = move.line;
  switch (move.path) {
    case PathControl::exact_stop:
      segment->term = Termination::stop;
      break;
    case PathControl::exact_path:
      segment->term = Termination::exact;
      break;
    case PathControl::blend:
      segment->term = Termination::parabolic;
      segment->tolerance = move.blend_tolerance_mm;
      break;
  }
  // M1: the nominal time runs the programmed length at the feed, capped by the axes and the
  // trajectory maximum (a rotary-only move is not under the latter).
  double v_nominal = segment->nominal_velocity;
  if (!segment->pure_rotary && machine.max_linear_velocity_mm_per_s &&
      *machine.max_linear_velocity_mm_per_s < v_nominal) {
    v_nominal = *machine.max_linear_velocity_mm_per_s;
    if (!segment->rapid) {
      segment->limit = Limit::axis_velocity;
      segment->feed_capped = true;
    }
  }
  segment->nominal_s = v_nominal > 0.0 ? segment->nominal_length / v_nominal : 0.0;
  return segment;
}

}  // namespace cutcalc::domain::machine_time
