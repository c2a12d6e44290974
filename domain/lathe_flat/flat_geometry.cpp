#include "domain/lathe_flat/flat_geometry.h"

#include <cmath>

#include "domain/common/numeric.h"

namespace cutcalc::domain::lathe_flat {

double depth_product_mm2(const FlatSection& flat) {
  const double r2 = flat.part_radius_mm;
  const double d = flat.axis_distance_mm;
  return flat.depth_mm.value_or(r2 - d) * (r2 + d);
}

double engagement_half_angle_rad(const FlatSection& flat) {
  return std::atan2(std::sqrt(depth_product_mm2(flat)), flat.axis_distance_mm);
}

double flat_width_mm(const FlatSection& flat) { return 2.0 * std::sqrt(depth_product_mm2(flat)); }

double tool_radius_position_mm(const FlatSection& flat, double alpha_rad) {
  return (flat.axis_distance_mm + flat.tool_radius_mm) / std::cos(alpha_rad);
}

double step_angle_rad(double alpha_e_rad, int steps, int i) {
  return alpha_e_rad * (1.0 - static_cast<double>(i) / steps);
}

double chord_mm(const FlatSection& flat, double alpha_from_rad, double alpha_to_rad) {
  return (flat.axis_distance_mm + flat.tool_radius_mm) *
         std::fabs(std::tan(alpha_from_rad) - std::tan(alpha_to_rad));
}

std::vector<StepRow> step_table(const FlatSection& flat, int steps) {
  const double alpha_e = engagement_half_angle_rad(flat);
  std::vector<StepRow> rows;
  rows.reserve(static_cast<std::size_t>(2 * steps + 1));
  for (int i = 0; i <= 2 * steps; ++i) {
    const double alpha = step_angle_rad(alpha_e, steps, i);
    StepRow row;
    row.i = i;
    row.c_deg = rad_times_180_over_pi(alpha);
    row.x_mm = tool_radius_position_mm(flat, alpha);
    if (i < 2 * steps) {
      const double next = step_angle_rad(alpha_e, steps, i + 1);
      row.dx_mm = row.x_mm - tool_radius_position_mm(flat, next);
      row.chord_mm = chord_mm(flat, alpha, next);
    }
    rows.push_back(row);
  }
  return rows;
}

}  // namespace cutcalc::domain::lathe_flat
