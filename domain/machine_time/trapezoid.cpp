#include "domain/machine_time/trapezoid.h"

#include <algorithm>
#include <cmath>

namespace cutcalc::domain::machine_time {

Trapezoid plan_trapezoid(double length, double v_start, double v_end, double v_max, double accel) {
  Trapezoid out;
  if (!(length > 0.0)) {
    out.v_end = v_start;
    return out;
  }
  if (!(v_max > 0.0)) {
    return out;
  }
  if (!(accel > 0.0) || !std::isfinite(accel)) {
    out.v_peak = v_max;
    out.v_end = v_max;
    out.cruise_s = length / v_max;
    out.duration_s = out.cruise_s;
    return out;
  }
  const double v0 = std::max(v_start, 0.0);
  double vf = std::clamp(v_end, 0.0, v_max);
  // The end velocity the length allows, accelerating or braking all the way.
  const double reach_up = v0 * v0 + 2.0 * accel * length;
  if (vf * vf > reach_up) {
    vf = std::sqrt(reach_up);
  }
  const double reach_down = v0 * v0 - 2.0 * accel * length;
  if (reach_down > vf * vf) {
    vf = std::sqrt(reach_down);  // cannot brake in time: the planner overshoots its final speed
  }
  const double peak_sq = (2.0 * accel * length + v0 * v0 + vf * vf) / 2.0;
  const double vp = std::max(std::min(v_max, std::sqrt(std::max(peak_sq, 0.0))), vf);
  const double d_first = std::fabs(vp * vp - v0 * v0) / (2.0 * accel);
  const double d_last = (vp * vp - vf * vf) / (2.0 * accel);
  const double cruise = std::max(length - d_first - d_last, 0.0);
  out.v_peak = vp;
  out.v_end = vf;
  out.accel_s = std::fabs(vp - v0) / accel;
  out.cruise_s = vp > 0.0 ? cruise / vp : 0.0;
  out.duration_s = out.accel_s + out.cruise_s + (vp - vf) / accel;
  return out;
}

}  // namespace cutcalc::domain::machine_time
