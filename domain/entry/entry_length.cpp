// compute_entry_length: one pass on the whole part (spec entry-and-main-time.md E1-E23, section 9).

#include "domain/entry/entry_length.h"

#include <cmath>

#include "domain/entry/contour_checks.h"
#include "domain/entry/contour_shape.h"
#include "domain/entry/pass.h"

namespace cutcalc::domain::entry {

namespace {

// The whole part is the workpiece: the band is limited by the contour's own edges +-h (E2, E3).
detail::PassSide whole_part_side(const Contour& contour, double offset_mm,
                                 double cutter_radius_mm) {
  const double h = detail::half_width_mm(contour);  // h
  return detail::PassSide{contour, detail::LateralSetting{offset_mm, cutter_radius_mm, -h, h}};
}

// Huge inputs can overflow (e.g. cot(alpha) of a nearly flat edge times B); no response may
// carry an infinity.
bool all_finite(const EntryLengthResult& result) {
  bool finite = std::isfinite(result.engagement_length_mm) &&
                std::isfinite(result.entry_length_mm) && std::isfinite(result.start.x_mm) &&
                std::isfinite(result.start.y_mm) && std::isfinite(result.steady_width_mm);
  if (result.exit) {
    finite = finite && std::isfinite(result.exit->end.x_mm) &&
             std::isfinite(result.exit->end.y_mm) && std::isfinite(result.exit->working_stroke_mm);
  }
  return finite;
}

}  // namespace

// E6-E9 through E10-E12
Result<EntryLengthResult> compute_entry_length(const EntryLengthParams& params) {
  const Contour* exit_contour = params.exit ? &params.exit->contour : nullptr;
  if (auto error = detail::check_arc_widths(params.entry, exit_contour)) {
    return *error;
  }
  if (exit_contour != nullptr) {
    if (auto error = detail::check_exit_width(*exit_contour, part_width_mm(params.entry))) {
      return *error;
    }
  }

  const double r = params.cutter_diameter_mm / 2.0;  // r (E1)
  const double K = params.offset_mm;                 // K
  detail::PassPlan plan;
  plan.approach_mm = params.approach_mm;
  plan.entry = whole_part_side(params.entry, K, r);
  if (params.exit) {
    // Entry and exit share the symmetry line (section 3), so the axis keeps its offset K.
    plan.exit =
        detail::PassExit{whole_part_side(params.exit->contour, K, r), params.exit->length_mm,
                         params.exit->extra_path_mm, params.exit->overrun_mm};
  }

  Result<detail::PassGeometry> pass = detail::solve_pass(plan);
  if (!pass.ok()) {
    return pass.error();
  }
  if (!all_finite(pass.value().result)) {
    return make_error(ErrorCode::not_converged, "the result is too large to represent");
  }
  return pass.value().result;
}

}  // namespace cutcalc::domain::entry
