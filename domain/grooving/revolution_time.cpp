#include "domain/grooving/revolution_time.h"

#include <algorithm>
#include <numbers>

namespace cutcalc::domain::grooving {
namespace {

// k = pi / (1000 v): minutes per revolution per mm of diameter under G96.
double css_slope(double cutting_speed_m_per_min) {
  return std::numbers::pi / (1000.0 * cutting_speed_m_per_min);
}

}  // namespace

double clamp_diameter_mm(const SpindleMode& spindle) {
  return 1.0 /
         (css_slope(spindle.cutting_speed_m_per_min.value_or(1.0)) * *spindle.max_spindle_rpm);
}

double minutes_per_revolution(const SpindleMode& spindle, double diameter_mm) {
  if (spindle.spindle_speed_rpm) return 1.0 / *spindle.spindle_speed_rpm;
  const double k = css_slope(*spindle.cutting_speed_m_per_min);
  return std::max(1.0 / *spindle.max_spindle_rpm, k * diameter_mm);
}

double mean_minutes_per_revolution(const SpindleMode& spindle, double d1_mm, double d2_mm) {
  const double lo = std::min(d1_mm, d2_mm);
  const double hi = std::max(d1_mm, d2_mm);
  if (spindle.spindle_speed_rpm || lo == hi) return minutes_per_revolution(spindle, lo);
  const double k = css_slope(*spindle.cutting_speed_m_per_min);
  const double at_limit = 1.0 / *spindle.max_spindle_rpm;
  const double d_star = clamp_diameter_mm(spindle);
  if (hi <= d_star) return at_limit;
  if (lo >= d_star) return k * (lo + hi) / 2.0;
  return (at_limit * (d_star - lo) + k * (hi * hi - d_star * d_star) / 2.0) / (hi - lo);
}

}  // namespace cutcalc::domain::grooving
