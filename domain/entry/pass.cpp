// E6-E9, E22 and E23 of spec entry-and-main-time.md on top of the E10-E12 engine.

#include "domain/entry/pass.h"

#include <string>

#include "domain/entry/contour_shape.h"

namespace cutcalc::domain::entry::detail {

namespace {

// Section 3: Y_n, Y_k are the frame Y of the axis y = K.
double axis_frame_y_mm(const PassSide& side) {
  return frame_y_mm(side.contour, side.lateral.axis_y_mm);
}

DomainError no_contact(const char* where) {
  return make_error(ErrorCode::no_contact,
                    std::string("the cutter does not reach the workpiece at the ") + where +
                        ": |offset| >= B/2 + D/2");
}

}  // namespace

// E6-E9, E22, E23
Result<PassGeometry> solve_pass(const PassPlan& plan) {
  const std::optional<Band> entry_band = steady_band(plan.entry.lateral);  // S (E2)
  if (!entry_band) {
    return no_contact("entry");
  }
  std::optional<Band> exit_band;  // S at the exit contour (E2)
  if (plan.exit) {
    exit_band = steady_band(plan.exit->side.lateral);
    if (!exit_band) {
      return no_contact("exit");
    }
  }

  const EntryExtremes psi = entry_extremes(plan.entry.contour, plan.entry.lateral, *entry_band);
  const double x_c0 = psi.first_contact_mm;  // xc0
  const double x_cs = psi.saturation_mm;     // xcs

  PassGeometry geometry;
  EntryLengthResult& result = geometry.result;
  result.engagement_length_mm = x_cs - x_c0;                                      // L_vr1 (E6)
  result.entry_length_mm = plan.approach_mm + result.engagement_length_mm;        // L_vr (E6)
  result.start = Position{plan.approach_mm - x_c0, axis_frame_y_mm(plan.entry)};  // X_n, Y_n (E7)
  result.steady_width_mm = entry_band->width_mm;                                  // W (E2)
  if (!plan.exit) {
    return geometry;
  }

  const PassExit& exit = *plan.exit;
  const bool wall = exit.side.contour.kind == ContourKind::wall;
  // E22: the periphery stops at the wall face, so the axis stays r short of it and never overruns.
  const double x_end = wall ? -exit.side.lateral.cutter_radius_mm
                            : exit_end_x_mm(exit.side.contour, exit.side.lateral, *exit_band);
  const double X_k = -x_end;                            // X_k (E8)
  const double overrun = wall ? 0.0 : exit.overrun_mm;  // L_per
  // E23: the steady travel straight from its terms; subtracting two rounded strokes could turn a
  // boundary case negative.
  const double steady_travel = exit.length_mm + exit.extra_path_mm + overrun - x_cs - X_k;
  if (steady_travel < 0.0) {
    return make_error(ErrorCode::stroke_shorter_than_entry);
  }
  ExitResult exit_result;
  exit_result.end = Position{X_k, axis_frame_y_mm(exit.side)};  // X_k, Y_k (E8)
  exit_result.working_stroke_mm =
      exit.length_mm + exit.extra_path_mm + result.start.x_mm - X_k + overrun;  // L_rx (E9)
  result.exit = exit_result;
  geometry.steady_travel_mm = steady_travel;
  return geometry;
}

}  // namespace cutcalc::domain::entry::detail
