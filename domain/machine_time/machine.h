#pragma once
// The machine a program is timed on (spec machine-time.md section 2), in the planner's units:
// mm (degrees for rotary axes) and seconds.

#include <array>
#include <optional>

#include "domain/machine_time/move.h"

namespace cutcalc::domain::machine_time {

struct AxisLimits {
  double max_velocity_per_s = 0.0;       // mm/s or deg/s
  double max_acceleration_per_s2 = 0.0;  // mm/s^2 or deg/s^2
};

struct Machine {
  std::array<std::optional<AxisLimits>, kAxisCount> axes{};  // absent: the machine has no such axis
  std::optional<double> max_linear_velocity_mm_per_s;        // [TRAJ] MAX_LINEAR_VELOCITY
  double servo_period_s = 0.001;                             // the trajectory period
  double max_spindle_rpm = 0.0;                              // 0: none

  [[nodiscard]] bool has(Axis axis) const { return axes[index(axis)].has_value(); }
};

}  // namespace cutcalc::domain::machine_time
