#include "domain/machine_time/blend.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "domain/common/numeric.h"
#include "domain/machine_time/planner.h"

namespace cutcalc::domain::machine_time {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kAngleEpsilon = 1e-6;          // TP_ANGLE_EPSILON
constexpr double kMinArcLength = 1e-6;          // TP_MIN_ARC_LENGTH
constexpr double kMinArcAngle = 1e-3;           // TP_MIN_ARC_ANGLE
constexpr double kBlendDistanceFraction = 0.5;  // BLEND_DIST_FRACTION
constexpr double kToleranceRatio = 0.25;        // tcFindBlendTolerance

bool is_curved(const Segment& s) { return s.shape != Shape::line; }

// The machine's X, Y, Z bounds; an absent axis is 0 (ignored, as LinuxCNC ignores it).
std::array<double, 3> xyz_bounds(const Machine& machine, bool velocity) {
  std::array<double, 3> bounds{};
  for (std::size_t i = 0; i < 3; ++i) {
    if (const auto& axis = machine.axes[i]) {
      bounds[i] = velocity ? axis->max_velocity_per_s : axis->max_acceleration_per_s2;
    }
  }
  return bounds;
}

// calculateInscribedDiameter: the largest magnitude of a vector in the plane with the unit
// normal `n` that keeps every axis within its bound.
double inscribed_limit(Vec3 n, const std::array<double, 3>& bounds) {
  const std::array<Vec3, 3> planar = {Vec3{1.0 - n.x * n.x, -n.x * n.y, -n.x * n.z},
                                      Vec3{-n.y * n.x, 1.0 - n.y * n.y, -n.y * n.z},
                                      Vec3{-n.z * n.x, -n.z * n.y, 1.0 - n.z * n.z}};
  double extent[3] = {0.0, 0.0, 0.0};
  double result = 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    Vec3 p{std::fabs(planar[i].x), std::fabs(planar[i].y), std::fabs(planar[i].z)};
    double& own = i == 0 ? p.x : i == 1 ? p.y : p.z;
    own = std::max(own, kPositionEpsilon);
    if (bounds[i] != 0.0) {
      extent[i] = bounds[i] / norm(p);
    }
    result = std::max(result, extent[i]);
  }
  for (std::size_t i = 0; i < 3; ++i) {
    if (bounds[i] != 0.0) {
      result = std::min(result, extent[i]);
    }
  }
  return result;
}

// tcGetMaxTargetVel: a segment synchronised to the spindle may go as fast as its axes allow (the
// spindle sets its speed as it runs), any other as fast as its feed.
double max_target_velocity_unscaled(const Segment& s) {
  return s.synced ? s.maxvel : std::min(s.reqvel, s.maxvel);
}

// findIntersectionAngle: half the angle between -u1 and u2 (pi/2 for a straight continuation).
double intersection_angle(Vec3 u1, Vec3 u2) {
  const double d = std::clamp(dot(u1, u2), -1.0, 1.0);
  return std::acos(-d) / 2.0;
}

}  // namespace

double overall_accel(const Segment& s) {
  double scale = 1.0 - std::max(s.kink_accel_reduce, s.kink_accel_reduce_prev);
  if (s.blend_prev || s.term == Termination::parabolic) {
    scale *= 0.5;  // two segments accelerate at once during a parabolic blend
  }
  return s.maxaccel * scale;
}

double tangential_accel(const Segment& s) {
  const double a = overall_accel(s);
  return is_curved(s) ? a * s.acc_ratio_tan : a;
}

double max_target_velocity(const Segment& s, const Machine& machine) {
  double v = max_target_velocity_unscaled(s);
  if (!s.pure_rotary && machine.max_linear_velocity_mm_per_s) {
    v = std::min(v, *machine.max_linear_velocity_mm_per_s);
  }
  return v;
}

double real_target_velocity(const Segment& s, const Machine& machine) {
  return std::min(s.reqvel, max_target_velocity(s, machine));
}

double triangle_velocity(const Segment& s) {
  double length = s.target;
  if (!s.finalized) {
    length /= 2.0;  // a blend may still take up to half of it
  }
  return std::sqrt(tangential_accel(s) * length);
}

TangentCheck setup_tangent(Segment& prev, Segment& next, const Machine& machine) {
  if (prev.rotary || next.rotary) {
    return TangentCheck::refused;
  }
  if (prev.term == Termination::stop) {
    return TangentCheck::refused;
  }
  const Vec3 u1 = prev.end_tangent;
  const Vec3 u2 = next.start_tangent;
  // pmCartCartAntiParallel within 2 degrees: a reversal stops.
  const double sharp_epsilon = std::pow(deg_to_rad(2.0), 2.0);
  if (dot(u1 + u2, u1 + u2) < sharp_epsilon) {
    prev.term = Termination::stop;
    next.blend_prev = false;
    return TangentCheck::refused;
  }
  const double v_max =
      std::min(max_target_velocity_unscaled(prev), max_target_velocity_unscaled(next));
  const double a_inst = v_max / machine.servo_period_s + next.maxaccel;
  const Vec3 diff = a_inst * (u2 - u1);
  const std::array<double, 3> bounds = xyz_bounds(machine, false);
  const double components[3] = {diff.x, diff.y, diff.z};
  double scale_max = 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    if (bounds[i] != 0.0) {
      scale_max = std::max(scale_max, std::fabs(components[i] / bounds[i]));
    }
  }
  if (is_curved(prev) || is_curved(next)) {
    scale_max /= kAccRatioTangential;
  }
  if (scale_max < kTangentKinkRatio) {
    prev.term = Termination::tangent;
    next.blend_prev = false;
    prev.kink_vel = v_max;
    prev.kink_accel_reduce = std::max(scale_max, prev.kink_accel_reduce);
    next.kink_accel_reduce_prev = std::max(scale_max, next.kink_accel_reduce_prev);
    return TangentCheck::tangent;
  }
  prev.kink_vel = v_max * kTangentKinkRatio / scale_max;
  prev.kink_accel_reduce = std::max(kTangentKinkRatio, prev.kink_accel_reduce);
  next.kink_accel_reduce_prev = std::max(kTangentKinkRatio, next.kink_accel_reduce_prev);
  return TangentCheck::corner;
}

std::optional<BlendArc> make_blend_arc(const Segment& prev, const Segment& next,
                                       const Machine& machine) {
  if (prev.term != Termination::parabolic || prev.rotary || next.rotary || prev.finalized ||
      next.finalized) {
    return std::nullopt;
  }
  const Vec3 u1 = prev.end_tangent;
  const Vec3 u2 = next.start_tangent;
  const double theta = intersection_angle(u1, u2);
  if (kPi / 2.0 - theta < kAngleEpsilon || theta < kAngleEpsilon) {
    return std::nullopt;
  }
  const Vec3 binormal = unit(cross(u1, u2));
  // An arc can only be blended in its own plane (pmUnitCartsColinear with its normal).
  for (const Segment* s : {&prev, &next}) {
    if (s->shape == Shape::arc && std::fabs(std::fabs(dot(binormal, s->normal)) - 1.0) > 1e-6) {
      return std::nullopt;
    }
  }
  const double phi = kPi - 2.0 * theta;

  // tcFindBlendTolerance: no tolerance (G64 without P) is a quarter of the shorter segment.
  double t1 = prev.tolerance > 0.0 ? prev.tolerance : prev.nominal_length * kToleranceRatio;
  double t2 = next.tolerance > 0.0 ? next.tolerance : next.nominal_length * kToleranceRatio;
  const double tolerance = std::min(
      {t1, t2, prev.nominal_length * kToleranceRatio, next.nominal_length * kToleranceRatio});

  const double a_max = inscribed_limit(binormal, xyz_bounds(machine, false));
  const double a_n_max = a_max * kNormalAccelRatio;
  const double v_req =
      std::max(max_target_velocity_unscaled(prev), max_target_velocity_unscaled(next));
  double v_goal = v_req;
  const double v_planar_max = inscribed_limit(binormal, xyz_bounds(machine, true));
  const double phi_effective = std::min(phi, kPi * 0.49);
  const double v_max1 = std::min(prev.maxvel, next.maxvel / std::cos(phi_effective));
  const double v_max2 = std::min(next.maxvel, prev.maxvel / std::cos(phi_effective));
  const double v_area = v_max1 * v_max2 / 2.0 * std::sin(phi);
  const double base = norm(v_max2 * u2 - v_max1 * u1);
  double v_max_alt = base > 0.0 ? 2.0 * v_area / base : 0.0;
  if (prev.shape != Shape::line || next.shape != Shape::line) {
    v_max_alt = 0.0;
  }
  v_goal = std::min(v_goal, std::max(v_max_alt, v_planar_max));

  // blendComputeParameters
  const double l1 = std::min(prev.target, prev.nominal_length * kBlendDistanceFraction);
  const double l2 = next.target * kBlendDistanceFraction;
  const double h_tol = tolerance / (1.0 - std::sin(theta));
  const double d_tol = std::cos(theta) * h_tol;
  const double d_geom = std::min({l1, l2, d_tol});
  const double r_geom = std::tan(theta) * d_geom;
  const double v_normal = std::sqrt(a_n_max * r_geom);
  const double v_plan = std::min(v_normal, v_goal);
  const double a_parabolic = a_max * 0.5;
  const double v_triangle = std::sqrt(2.0 * a_parabolic * d_geom);
  const double t_blend = std::min(v_triangle, v_plan) / a_parabolic;
  const double s_blend = t_blend * v_plan;
  const double r_blend = std::min(s_blend / phi, r_geom);
  const double r_plan = std::max(v_plan * v_plan / a_n_max, r_blend);
  const double d_plan = r_plan / std::tan(theta);
  const double s_arc = r_plan * phi;
  if (!(r_plan >= kPositionEpsilon) || !(s_arc >= kMinArcLength) || !std::isfinite(d_plan)) {
    return std::nullopt;
  }

  BlendArc blend;
  blend.trim = d_plan;
  Segment& arc = blend.arc;
  arc.shape = Shape::blend_arc;
  arc.rapid = prev.rapid;
  arc.line = prev.line;
  arc.target = s_arc;
  arc.nominal_length = s_arc;
  // A blend arc takes the planner's state when it is made (tcSetupState): synchronised to the
  // spindle when the next block is, at that block's feed per revolution.
  arc.synced = next.synced;
  arc.reqvel = next.synced ? next.reqvel : v_req;
  arc.maxvel = v_plan;
  arc.maxaccel = a_max;
  arc.term = Termination::tangent;
  arc.tolerance = prev.tolerance;
  arc.start_tangent = u1;
  arc.end_tangent = u2;
  arc.end_point = next.end_point;  // not used once the arc is built
  arc.arc_radius = r_plan;
  arc.limit = Limit::blend;
  arc.finalized = true;
  arc.maxvel = std::min(arc.maxvel, arc.target / machine.servo_period_s);

  // blendCheckConsume: a previous line left shorter than a few servo periods at the blend's speed
  // goes into the arc (only lines; not one a parabolic blend runs into).
  if (prev.shape == Shape::line && !prev.blend_prev) {
    const double rest = prev.target - d_plan;
    if (rest / v_plan < kBlendGapCycles * machine.servo_period_s) {
      blend.consume = true;
      arc.target += rest;
      arc.maxvel = std::min(v_plan, arc.target / machine.servo_period_s);
    }
  }
  return blend;
}

ParabolicBlend parabolic_blend(const Segment& segment, const Segment& next, double target_this,
                               double target_next) {
  const double acc_this = tangential_accel(segment);
  const double acc_next = tangential_accel(next);
  const double v_reach_this = std::min(triangle_velocity(segment), target_this);
  const double v_reach_next = std::min(triangle_velocity(next), target_next);
  ParabolicBlend out;
  if (!(v_reach_this > 0.0) || !(v_reach_next > 0.0) || !(acc_this > 0.0) || !(acc_next > 0.0)) {
    return out;
  }
  const double t_max_reachable =
      std::min(segment.target / v_reach_this, next.target / v_reach_next);
  const double t_max_blend = std::max(v_reach_this / acc_this, v_reach_next / acc_next);
  const double t_blend = std::min(t_max_reachable, t_max_blend);
  out.v_this = std::min(v_reach_this, t_blend * acc_this);
  out.v_next = std::min(v_reach_next, t_blend * acc_next);
  // theta = acos(-d) / 2 (intersection_angle) by its half-angle identities: no trigonometry on
  // the path every blended segment takes.
  const double d = std::clamp(dot(segment.end_tangent, next.start_tangent), -1.0, 1.0);
  const double cos_theta = std::sqrt((1.0 - d) / 2.0);
  const double sin_theta = std::sqrt((1.0 + d) / 2.0);
  static const double kMinCosTheta = std::cos(kPi / 2.0 - kMinArcAngle);
  if (segment.tolerance > 0.0 && cos_theta > kMinCosTheta) {
    const double v_tolerance = 2.0 * std::sqrt(acc_this * segment.tolerance / cos_theta);
    out.v_this = std::min(out.v_this, v_tolerance);
    out.v_next = std::min(out.v_next, v_tolerance);
  }
  out.v_net = sin_theta * (out.v_this + out.v_next) / 2.0;
  return out;
}

}  // namespace cutcalc::domain::machine_time
