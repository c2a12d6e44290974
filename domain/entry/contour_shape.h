#pragma once
// Contour functions of section 3 in the internal frame: x along the feed (+ downstream), y lateral,
// y = 0 on the strip's symmetry line (straight, concave arc, wall) or the arc axis (arcs).
// Private to domain/entry.

#include "domain/entry/contour.h"

namespace cutcalc::domain::entry::detail {

// sin, cos and cot of an edge angle in degrees; exactly 1, 0, 0 at 90 so that perpendicular edges
// carry no rounding noise (section 6.2).
struct EdgeTrig {
  double sin_alpha = 1.0;  // sin(alpha)
  double cos_alpha = 0.0;  // cos(alpha)
  double cot_alpha = 0.0;  // cot(alpha)
};
EdgeTrig edge_trig(double angle_deg);

// E3: h, half the width the contour spans.
double half_width_mm(const Contour& contour);

// e(y) (section 3): the entry region is x >= e(y) for |y| <= h.
double entry_edge_x_mm(const Contour& contour, double y_mm);

// f(y) (section 3): the exit region is x <= f(y) for |y| <= h. A wall has no such function (E22).
double exit_edge_x_mm(const Contour& contour, double y_mm);

// Section 3: the workpiece frame's Y of the internal lateral y. Straight edges and walls measure Y
// from the side edge (Y = y + h), arcs from the arc axis (Y = y).
double frame_y_mm(const Contour& contour, double y_mm);

}  // namespace cutcalc::domain::entry::detail
