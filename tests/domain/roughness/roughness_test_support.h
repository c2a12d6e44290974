#pragma once
// Shorthands and the independent tool-boundary oracle shared by the roughness tests
// (spec shared/domain/roughness.md).

#include <algorithm>
#include <cmath>
#include <limits>

#include "domain/common/milling_sense.h"

namespace cutcalc::test::roughness {

inline constexpr domain::MillingSense kUp = domain::MillingSense::up;
inline constexpr domain::MillingSense kDown = domain::MillingSense::down;

// Tolerance for a number the spec prints with `last_digit` as its last place: half of it, plus
// the rounding of the calculation (bore milling: 1e-15, groove wall: 1e-12).
constexpr double bore_printed(double last_digit) { return 0.5 * last_digit + 1e-15; }
constexpr double wall_printed(double last_digit) { return 0.5 * last_digit + 1e-12; }

// The tool's upper boundary at x with its corner at x = 0 (nose arc of radius rho, minor edge at
// phi1 tangent to it, nothing beyond the main edge), in long double. No branch formula is used.
inline long double tool_boundary(long double x, long double rho, long double phi1) {
  if (x > rho) {
    return -std::numeric_limits<long double>::infinity();  // beyond the main edge: no tool
  }
  if (x >= -rho * std::sin(phi1)) {
    return std::sqrt(std::max(rho * rho - x * x, 0.0L));  // nose arc
  }
  return x * std::tan(phi1) + rho / std::cos(phi1);  // minor edge, tangent to the arc
}

}  // namespace cutcalc::test::roughness
