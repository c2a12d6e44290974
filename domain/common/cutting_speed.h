#pragma once
// The spindle speed that gives a cutting speed on a diameter: the milling cutter's (entry feeds)
// and the groove bottom's (the grooving cycle's G96 limit warning, grooving-cycle.md K23).

#include <numbers>

namespace cutcalc::domain {

// E30 (entry-and-main-time.md): n = 1000 v / (pi D), rev/min for v in m/min and D in mm; not
// rounded to machine steps.
inline double spindle_speed_rpm_at(double cutting_speed_m_per_min, double diameter_mm) {
  return 1000.0 * cutting_speed_m_per_min / (std::numbers::pi * diameter_mm);
}

}  // namespace cutcalc::domain
