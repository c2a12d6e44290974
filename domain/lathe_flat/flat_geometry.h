#pragma once
// The geometry of a flat milled on a lathe by C-axis steps with X following (spec lathe-flat.md
// section 3, F1-F9; paper 000, Figs. 12-13): the flat's plane at distance d from the part axis,
// its engagement half-angle, the step points and the blocks between them. Units: mm, radians
// inside (degrees only in the C words).

#include <optional>
#include <vector>

namespace cutcalc::domain::lathe_flat {

// The flat of one layer as the tool sees it.
struct FlatSection {
  double part_radius_mm = 0.0;    // R2
  double axis_distance_mm = 0.0;  // d
  double tool_radius_mm = 0.0;    // R
  // t = R2 - d when known without cancellation (given, or from b): keeps (R2 - d)(R2 + d) exact
  // for a flat shallow against the part.
  std::optional<double> depth_mm{};
};

// (R2 - d)(R2 + d), from t when the section has it.
double depth_product_mm2(const FlatSection& flat);

// F2: alpha_e = atan2(sqrt((R2 - d)(R2 + d)), d), radians.
double engagement_half_angle_rad(const FlatSection& flat);
// F3: b = 2 sqrt((R2 - d)(R2 + d)).
double flat_width_mm(const FlatSection& flat);
// F5: X(alpha) = (d + R) / cos(alpha), the tool reference point's radius.
double tool_radius_position_mm(const FlatSection& flat, double alpha_rad);
// F6: alpha_i = alpha_e (1 - i/N), i = 0..2N.
double step_angle_rad(double alpha_e_rad, int steps, int i);
// F9: chord_i = (d + R) |tan(alpha_i) - tan(alpha_(i+1))|.
double chord_mm(const FlatSection& flat, double alpha_from_rad, double alpha_to_rad);

// One row of the step table (F5-F9): step point i of flat 1.
struct StepRow {
  int i = 0;
  double c_deg = 0.0;     // C_(0,i) (F7)
  double x_mm = 0.0;      // X(alpha_i), a radius
  double dx_mm = 0.0;     // X_i - X_(i+1) (F8); 0 in the last row
  double chord_mm = 0.0;  // F9; 0 in the last row
};
std::vector<StepRow> step_table(const FlatSection& flat, int steps);

}  // namespace cutcalc::domain::lathe_flat
