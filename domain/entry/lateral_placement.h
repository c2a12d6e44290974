#pragma once
// Lateral placement of the passes across the part and the one-pass problem of each (E26-E29,
// section 7.2). Private to domain/entry.

#include <cstddef>
#include <vector>

#include "domain/entry/main_time.h"
#include "domain/entry/pass.h"

namespace cutcalc::domain::entry::detail {

// Where lateral pass i sits, in the part frame Y_p = y + h (from the side edge).
struct LateralFrame {
  double lower_boundary_mm = 0.0;  // Y_(i-1): the strip still uncut at this depth is [Y_(i-1), B]
  double axis_y_mm = 0.0;          // Y_ax,i
  double offset_mm = 0.0;          // K_i, from the strip's centre
  double strip_width_mm = 0.0;     // B_i
};

// E26 (count 1, axis at the offset K) and E27-E28 (count > 1, offset must be absent).
std::vector<LateralFrame> place_lateral_passes(std::size_t count, double part_width_mm,
                                               double width_of_cut_mm, double cutter_radius_mm,
                                               double offset_mm);

// E29: the one-pass problem of a lateral pass, in the strip's frames for straight contours and
// walls, in the whole arc's frame for arcs.
PassPlan plan_lateral_pass(const MainTimeParams& params, const LateralFrame& frame);

}  // namespace cutcalc::domain::entry::detail
