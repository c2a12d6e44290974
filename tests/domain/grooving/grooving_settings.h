#pragma once
// The grooving cycles the domain tests start from.

#include <optional>

#include "domain/grooving/grooving_cycle.h"

namespace cutcalc::domain::grooving::settings {

// Spec section 7: W 10.4, X2 0.4, D0 220, depth 4.8, S0 0.12, v 86 m/min, n_max 1000, rho 0.3,
// phi1 2 deg, c 1, dwell 1 rev.
inline GroovingCycleParams paper_setting() {
  GroovingCycleParams p;
  p.groove_width_mm = 10.4;
  p.start_diameter_mm = 220.0;
  p.groove_depth_mm = 4.8;
  p.groove_left_z_mm = -20.0;
  p.shift_mm = 0.4;
  p.feed_per_rev_mm = 0.12;
  p.spindle = {std::nullopt, 86.0, 1000.0};
  p.nose_radius_mm = 0.3;
  p.minor_edge_angle_deg = 2.0;
  return p;
}

// A small groove at constant speed: W 3, X2 0.4, D0 50, depth N x 0.1 at S0 0.1, z_L -10,
// n 500 rpm (G97), dwell 1 rev.
inline GroovingCycleParams small_groove(int revolutions) {
  GroovingCycleParams p;
  p.groove_width_mm = 3.0;
  p.start_diameter_mm = 50.0;
  p.groove_depth_mm = 0.1 * revolutions;
  p.groove_left_z_mm = -10.0;
  p.shift_mm = 0.4;
  p.feed_per_rev_mm = 0.1;
  p.spindle = {500.0, std::nullopt, std::nullopt};
  p.nose_radius_mm = 0.4;
  p.minor_edge_angle_deg = 3.0;
  return p;
}

}  // namespace cutcalc::domain::grooving::settings
