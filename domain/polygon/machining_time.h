#pragma once
// The program's machining time, spec polygon-holes.md section 13 (P32-P34; by analogy with
// programs.md G8-G11). Private to domain/polygon.

#include "domain/polygon/polygon_hole.h"

namespace cutcalc::domain::polygon::detail {

// What the time depends on, mm, rev/min, mm/min; from unrounded values. No defaults of its own:
// the caller passes the request's (PolygonHoleParams states them).
struct TimeInputs {
  int N = 4;
  double layers = 1.0;             // n (P22)
  double dz_mm = 0.0;              // dz (P22)
  int loops_per_layer = 1;         // lpl
  double spindle_speed_rpm = 0.0;  // S
  double loop_length_mm = 0.0;     // L_p (P23)
  double feed_per_rev_mm = 0.0;    // (N - 1) L_p
  double safe_z_mm = 0.0;
  double depth_mm = 0.0;
  double rapid_mm_per_min = 0.0;
  Synchronization synchronization = Synchronization::feed_per_rev;
  // G95 ramp F modal at `G1 Z0` (linuxcnc and sinumerik): the plunge runs at the ramp F.
  bool plunge_at_ramp_feed = true;
};

// P32-P34.
MachiningTime machining_time(const TimeInputs& in);

}  // namespace cutcalc::domain::polygon::detail
