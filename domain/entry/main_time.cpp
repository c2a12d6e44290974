// compute_main_time: the whole setup of N1 lateral x N2 depth passes (spec entry-and-main-time.md
// E24-E36, section 7).

#include "domain/entry/main_time.h"

#include <cmath>
#include <cstddef>
#include <vector>

#include "domain/entry/allowance_checks.h"
#include "domain/entry/contour_checks.h"
#include "domain/entry/feeds.h"
#include "domain/entry/lateral_placement.h"
#include "domain/entry/pass.h"
#include "domain/entry/passes.h"

namespace cutcalc::domain::entry {

namespace {

// E34: one traverse of lateral pass i.
void set_times(LateralPass& pass, double steady_travel_mm, const detail::Feeds& feeds) {
  pass.entry_time_min = pass.entry_length_mm / feeds.entry_feed_mm_per_min;  // t_e,i
  pass.steady_time_min = steady_travel_mm / feeds.feed_mm_per_min;           // t_s,i
  pass.time_min = pass.entry_time_min + pass.steady_time_min;                // t_i
}

LateralPass to_lateral_pass(const detail::LateralFrame& frame, const detail::PassGeometry& geometry,
                            const detail::Feeds& feeds) {
  const EntryLengthResult& one = geometry.result;
  LateralPass pass;
  pass.width_mm = one.steady_width_mm;         // W_i
  pass.axis_y_mm = frame.axis_y_mm;            // Y_ax,i
  pass.offset_mm = frame.offset_mm;            // K_i
  pass.strip_width_mm = frame.strip_width_mm;  // B_i
  pass.engagement_length_mm = one.engagement_length_mm;
  pass.entry_length_mm = one.entry_length_mm;
  pass.start = one.start;
  pass.end = one.exit->end;
  pass.working_stroke_mm = one.exit->working_stroke_mm;
  set_times(pass, geometry.steady_travel_mm, feeds);
  return pass;
}

// Huge inputs can overflow (e.g. a tiny feed and a long stroke); no response may carry an infinity.
bool all_finite(const MainTimeResult& result) {
  bool finite = std::isfinite(result.spindle_speed_rpm) && std::isfinite(result.feed_per_rev_mm) &&
                std::isfinite(result.feed_mm_per_min) &&
                std::isfinite(result.entry_feed_mm_per_min) &&
                std::isfinite(result.main_time_min) && std::isfinite(result.entry_time_min) &&
                std::isfinite(result.steady_time_min);
  for (const double depth : result.depth_passes_mm) {
    finite = finite && std::isfinite(depth);
  }
  for (const LateralPass& pass : result.lateral_passes) {
    for (const double value :
         {pass.width_mm, pass.axis_y_mm, pass.offset_mm, pass.strip_width_mm,
          pass.engagement_length_mm, pass.entry_length_mm, pass.start.x_mm, pass.start.y_mm,
          pass.end.x_mm, pass.end.y_mm, pass.working_stroke_mm, pass.entry_time_min,
          pass.steady_time_min, pass.time_min}) {
      finite = finite && std::isfinite(value);
    }
  }
  return finite;
}

}  // namespace

// E24-E36. Checks on fields alone come first, then the contours, then the pass counts; geometry
// runs last.
Result<MainTimeResult> compute_main_time(const MainTimeParams& params) {
  if (auto error = detail::check_width_of_cut(params)) {
    return *error;
  }
  Result<detail::Feeds> feeds = detail::compute_feeds(params);  // E30-E33
  if (!feeds.ok()) {
    return feeds.error();
  }
  if (auto error = detail::check_arc_widths(params.entry, &params.exit)) {
    return *error;
  }
  const double B = part_width_mm(params.entry);  // B (section 7.2)
  if (auto error = detail::check_exit_width(params.exit, B)) {
    return *error;
  }
  if (auto error = detail::check_allowance_width(params, B)) {
    return *error;
  }

  const Allowance& allowance = params.allowance;
  const Result<std::size_t> N1 =
      detail::pass_count(allowance.width_mm, allowance.width_of_cut_mm,
                         ErrorCode::too_many_lateral_passes);  // N1 (E24)
  if (!N1.ok()) {
    return N1.error();
  }
  const Result<std::size_t> N2 = detail::pass_count(allowance.depth_mm, allowance.depth_of_cut_mm,
                                                    ErrorCode::too_many_depth_passes);  // N2 (E24)
  if (!N2.ok()) {
    return N2.error();
  }
  if (N1.value() > 1) {
    if (auto error = detail::check_several_passes(params, B)) {
      return *error;
    }
  }

  MainTimeResult result;
  result.spindle_speed_rpm = feeds.value().spindle_speed_rpm;
  result.feed_per_rev_mm = feeds.value().feed_per_rev_mm;
  result.feed_mm_per_min = feeds.value().feed_mm_per_min;
  result.entry_feed_mm_per_min = feeds.value().entry_feed_mm_per_min;
  result.depth_passes_mm =
      detail::pass_sizes(N2.value(), allowance.depth_mm, allowance.depth_of_cut_mm);  // E25

  const double r = params.cutter_diameter_mm / 2.0;  // r (E1)
  const std::vector<detail::LateralFrame> frames = detail::place_lateral_passes(
      N1.value(), B, allowance.width_of_cut_mm, r, params.offset_mm.value_or(0.0));
  double entry_time_one_level = 0.0;   // sum_i t_e,i
  double steady_time_one_level = 0.0;  // sum_i t_s,i
  double time_one_level = 0.0;         // sum_i t_i
  result.lateral_passes.reserve(frames.size());
  for (const detail::LateralFrame& frame : frames) {
    Result<detail::PassGeometry> geometry =
        detail::solve_pass(detail::plan_lateral_pass(params, frame));  // E29
    if (!geometry.ok()) {
      return geometry.error();
    }
    const LateralPass& pass =
        result.lateral_passes.emplace_back(to_lateral_pass(frame, geometry.value(), feeds.value()));
    entry_time_one_level += pass.entry_time_min;
    steady_time_one_level += pass.steady_time_min;
    time_one_level += pass.time_min;
  }

  // E35-E36: every depth level repeats the same lateral passes.
  const double levels = static_cast<double>(N2.value());  // N2
  result.main_time_min = levels * time_one_level;         // T_o
  result.entry_time_min = levels * entry_time_one_level;
  result.steady_time_min = levels * steady_time_one_level;
  if (!all_finite(result)) {
    return make_error(ErrorCode::not_converged, "the result is too large to represent");
  }
  return result;
}

}  // namespace cutcalc::domain::entry
