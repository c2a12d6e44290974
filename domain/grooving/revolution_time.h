#pragma once
// The time of one spindle revolution on a lathe, at constant speed (G97) or at constant surface
// speed with a maximum speed (G96), and its mean over a radial move (spec grooving-cycle.md K15,
// K16). Units: mm, m/min, rev/min; times in minutes per revolution.

#include <optional>

namespace cutcalc::domain::grooving {

struct SpindleMode {
  std::optional<double> spindle_speed_rpm;        // n: G97 (exactly one of n and v)
  std::optional<double> cutting_speed_m_per_min;  // v: G96
  std::optional<double> max_spindle_rpm;          // n_max: required with v; with n a warning limit
};

// K15: 1/n(D), minutes per revolution at diameter D.
double minutes_per_revolution(const SpindleMode& spindle, double diameter_mm);

// K16: M(D1, D2), the mean of 1/n(D) over a diameter changing linearly from D1 to D2 (either
// order); a block of r revolutions over it takes r * M.
double mean_minutes_per_revolution(const SpindleMode& spindle, double d1_mm, double d2_mm);

// The diameter below which G96 runs at n_max: D* = 1000 v / (pi n_max).
double clamp_diameter_mm(const SpindleMode& spindle);

}  // namespace cutcalc::domain::grooving
