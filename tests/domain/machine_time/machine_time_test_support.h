#pragma once
// Machines and programs for the machine-time tests.

#include <string>
#include <string_view>

#include "domain/machine_time/program_time.h"

namespace cutcalc::domain::machine_time::test {

// The reference file's router: X/Y 12 m/min at 1000 mm/s^2, Z 8 m/min at 600, 12 m/min
// trajectory maximum, 1 ms servo period.
inline Machine router() {
  Machine machine;
  machine.axes[index(Axis::x)] = AxisLimits{12000.0 / 60.0, 1000.0};
  machine.axes[index(Axis::y)] = AxisLimits{12000.0 / 60.0, 1000.0};
  machine.axes[index(Axis::z)] = AxisLimits{8000.0 / 60.0, 600.0};
  machine.max_linear_velocity_mm_per_s = 12000.0 / 60.0;
  machine.servo_period_s = 0.001;
  return machine;
}

inline ProgramTime time_of(std::string_view program, const Machine& machine = router(),
                           program::Dialect dialect = program::Dialect::linuxcnc,
                           int profile_points = 0) {
  ProgramTimeParams params;
  params.program = program;
  params.read.dialect = dialect;
  params.machine = machine;
  params.profile_points = profile_points;
  ProgramTimeOutcome outcome = time_program(params);
  return std::get<ProgramTime>(std::move(outcome));
}

}  // namespace cutcalc::domain::machine_time::test
