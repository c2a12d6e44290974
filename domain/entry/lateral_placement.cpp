// E26-E29 and the strip frames of section 7.2 (spec entry-and-main-time.md).

#include "domain/entry/lateral_placement.h"

#include "domain/entry/contour_shape.h"

namespace cutcalc::domain::entry::detail {

namespace {

bool measured_from_side_edge(const Contour& contour) {
  return contour.kind == ContourKind::straight || contour.kind == ContourKind::wall;
}

// Section 7.2: a straight edge (or wall) of the strip [Y_(i-1), B] is the part's edge cut down to
// the strip, with its own corner as origin and its own centre line for K_i. An arc keeps the
// whole arc's function and frame; only the band's lower limit moves to the strip's edge
// (inferred). Both contours share the centre line, so the exit uses the same K_i as the entry.
PassSide strip_side(const Contour& contour, const LateralFrame& frame, double cutter_radius_mm) {
  const double Y_prev = frame.lower_boundary_mm;  // Y_(i-1)
  if (measured_from_side_edge(contour)) {
    Contour strip = contour;
    strip.width_mm = part_width_mm(contour) - Y_prev;  // B_i
    const double h_i = strip.width_mm.value() / 2.0;   // h of the strip
    return PassSide{strip, LateralSetting{frame.offset_mm, cutter_radius_mm, -h_i, h_i}};
  }
  const double h = half_width_mm(contour);  // h
  // The strip's centre lies at y = Y_(i-1)/2 in the arc frame, hence y_ax = K_i + Y_(i-1)/2
  // (exactly K for a single pass).
  const double axis_y = frame.offset_mm + Y_prev / 2.0;
  return PassSide{contour, LateralSetting{axis_y, cutter_radius_mm, Y_prev - h, h}};
}

// How far downstream the strip's origin lies from the part's: a straight edge's corner moves by
// Y_(i-1) cot(alpha) along the feed (inferred); arcs and walls keep the part's origin.
double origin_shift_mm(const Contour& contour, double lower_boundary_mm) {
  if (contour.kind != ContourKind::straight) {
    return 0.0;
  }
  return lower_boundary_mm * edge_trig(contour.angle_deg).cot_alpha;
}

}  // namespace

// E26-E28
std::vector<LateralFrame> place_lateral_passes(std::size_t count, double part_width_mm,
                                               double width_of_cut_mm, double cutter_radius_mm,
                                               double offset_mm) {
  const double B = part_width_mm;     // B
  const double t = width_of_cut_mm;   // t
  const double r = cutter_radius_mm;  // r
  if (count == 1) {
    // E26: the whole part is the workpiece and the axis sits at K from its centre.
    return {LateralFrame{0.0, B / 2.0 + offset_mm, offset_mm, B}};
  }
  std::vector<LateralFrame> frames;
  frames.reserve(count);
  for (std::size_t i = 1; i <= count; ++i) {
    LateralFrame frame;
    frame.lower_boundary_mm = static_cast<double>(i - 1) * t;  // Y_(i-1) (E27)
    frame.strip_width_mm = B - frame.lower_boundary_mm;        // B_i
    const double strip_centre = (frame.lower_boundary_mm + B) / 2.0;
    if (i < count) {
      // E27: the cutter's +Y edge on the boundary Y_i, so that it cuts exactly [Y_(i-1), Y_i].
      const double Y_i = static_cast<double>(i) * t;     // Y_i
      frame.axis_y_mm = Y_i - r;                         // Y_ax,i
      frame.offset_mm = frame.axis_y_mm - strip_centre;  // K_i (E28)
    } else {
      frame.axis_y_mm = strip_centre;  // Y_ax,N1: centre of the remaining strip
      frame.offset_mm = 0.0;           // K_N1 (E28)
    }
    frames.push_back(frame);
  }
  return frames;
}

// E29
PassPlan plan_lateral_pass(const MainTimeParams& params, const LateralFrame& frame) {
  const double r = params.cutter_diameter_mm / 2.0;  // r (E1)
  const double Y_prev = frame.lower_boundary_mm;     // Y_(i-1)
  PassPlan plan;
  plan.approach_mm = params.approach_mm;
  plan.entry = strip_side(params.entry, frame, r);
  // L_i = L + Y_(i-1) (cot(alpha_x) - cot(alpha)) for straight contours (inferred).
  const double length_i = params.length_mm + origin_shift_mm(params.exit, Y_prev) -
                          origin_shift_mm(params.entry, Y_prev);
  plan.exit = PassExit{strip_side(params.exit, frame, r), length_i, params.extra_path_mm,
                       params.overrun_mm};
  return plan;
}

}  // namespace cutcalc::domain::entry::detail
