#pragma once
// A segment's trapezoidal velocity profile (spec machine-time.md M3; LinuxCNC 2.9 has no jerk
// limit): from v_start, up to at most v_max, down to v_end, at acceleration a, over a length.

namespace cutcalc::domain::machine_time {

struct Trapezoid {
  double duration_s = 0.0;
  double v_peak = 0.0;
  double v_end = 0.0;  // v_end as asked, or lower when the length cannot reach it
  double accel_s = 0.0;
  double cruise_s = 0.0;
};

Trapezoid plan_trapezoid(double length, double v_start, double v_end, double v_max, double accel);

}  // namespace cutcalc::domain::machine_time
