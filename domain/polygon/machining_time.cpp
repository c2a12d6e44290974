// P32-P34 of spec polygon-holes.md: working, plunge, rapid and cycle time of the program.

#include "domain/polygon/machining_time.h"

#include <cmath>

namespace cutcalc::domain::polygon::detail {

MachiningTime machining_time(const TimeInputs& in) {
  const double n = in.layers;
  const double lpl = in.loops_per_layer;
  const double S = in.spindle_speed_rpm;
  // The ramp loop is longer than a flat one by sqrt(1 + (dz/L_p)^2).
  const double slope = in.dz_mm / in.loop_length_mm;
  const double ramp_factor = std::sqrt(1.0 + slope * slope);
  MachiningTime time;
  // P32: one loop is 1/(N-1) spindle revolution; with 1 loop per layer a flat loop ends the cut.
  const double loops = n * lpl + (in.loops_per_layer == 1 ? 1.0 : 0.0);
  const double T_loop = 1.0 / ((in.N - 1.0) * S);
  time.working_min = loops * T_loop;
  if (in.synchronization == Synchronization::c_axis) {
    time.working_min += n * T_loop * (ramp_factor - 1.0);  // G94 F along XYZ
  }
  // P33: F_a the plunge feed.
  const double flat_feed = S * in.feed_per_rev_mm;
  const double F_a = in.synchronization == Synchronization::feed_per_rev && in.plunge_at_ramp_feed
                         ? flat_feed * ramp_factor
                         : flat_feed;
  time.plunge_min = in.safe_z_mm / F_a;
  // P34
  time.rapid_min = (in.depth_mm + in.safe_z_mm) / in.rapid_mm_per_min;
  time.cycle_min = time.working_min + time.plunge_min + time.rapid_min;
  return time;
}

}  // namespace cutcalc::domain::polygon::detail
