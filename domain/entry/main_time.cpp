// compute_main_time: the whole setup of N1 lateral x N2 depth passes (spec entry-and-main-time.md
// E24-E41, sections 7 and 15).

#include "domain/entry/main_time.h"

#include <cmath>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "domain/entry/allowance_checks.h"
#include "domain/entry/contour_checks.h"
#include "domain/entry/feeds.h"
#include "domain/entry/lateral_placement.h"
#include "domain/entry/pass.h"
#include "domain/entry/passes.h"

namespace cutcalc::domain::entry {

namespace {

// E34 (and E41 at the finishing feeds): one traverse of a lateral pass of entry length L_vr,i
// and steady travel L_rx,i - L_vr,i.
PassTimes traverse_times(double entry_length_mm, double steady_travel_mm,
                         const detail::Feeds& feeds) {
  PassTimes times;
  times.entry_time_min = entry_length_mm / feeds.entry_feed_mm_per_min;  // t_e,i
  times.steady_time_min = steady_travel_mm / feeds.feed_mm_per_min;      // t_s,i
  times.time_min = times.entry_time_min + times.steady_time_min;         // t_i
  return times;
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
  const PassTimes times = traverse_times(pass.entry_length_mm, geometry.steady_travel_mm, feeds);
  pass.entry_time_min = times.entry_time_min;
  pass.steady_time_min = times.steady_time_min;
  pass.time_min = times.time_min;
  pass.lower_boundary_mm = frame.lower_boundary_mm;
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
  if (result.finish) {
    const FinishLevel& finish = *result.finish;
    for (const double value : {finish.spindle_speed_rpm, finish.feed_per_rev_mm,
                               finish.feed_mm_per_min, finish.entry_feed_mm_per_min,
                               finish.entry_time_min, finish.steady_time_min, finish.time_min}) {
      finite = finite && std::isfinite(value);
    }
    for (const PassTimes& times : finish.lateral_passes) {
      finite = finite && std::isfinite(times.time_min);
    }
  }
  return finite;
}

// E24-E25, E37, E39: the depth levels, roughing first, the finishing depth t_f last.
Result<std::vector<double>> depth_levels(const MainTimeParams& params) {
  const Allowance& allowance = params.allowance;
  double roughing_mm = allowance.depth_mm;  // H, or H_r = H - t_f (E39)
  if (params.finish) {
    // E39: at least one roughing level.
    if (params.finish->depth_of_cut_mm >= allowance.depth_mm) {
      return make_error(ErrorCode::finish_depth_not_below_depth);
    }
    roughing_mm -= params.finish->depth_of_cut_mm;
  }
  const Result<std::size_t> levels = detail::pass_count(
      roughing_mm, allowance.depth_of_cut_mm, ErrorCode::too_many_depth_passes);  // N2 or N2r
  if (!levels.ok()) {
    return levels.error();
  }
  std::vector<double> depths =
      detail::pass_sizes(levels.value(), roughing_mm, allowance.depth_of_cut_mm, params.pass_split);
  if (params.finish) {
    depths.push_back(params.finish->depth_of_cut_mm);  // t_f: N2 = N2r + 1
  }
  return depths;
}

// E40-E41: one traverse of every lateral pass at the finishing feeds.
FinishLevel finish_level(double depth_mm, const detail::Feeds& feeds,
                         const std::vector<LateralPass>& passes,
                         const std::vector<double>& steady_travels_mm) {
  FinishLevel level;
  level.depth_mm = depth_mm;                                  // t_f
  level.spindle_speed_rpm = feeds.spindle_speed_rpm;          // n_f
  level.feed_per_rev_mm = feeds.feed_per_rev_mm;              // z S_zf
  level.feed_mm_per_min = feeds.feed_mm_per_min;              // S_m2f
  level.entry_feed_mm_per_min = feeds.entry_feed_mm_per_min;  // S_m1f
  for (std::size_t i = 0; i < passes.size(); ++i) {
    const PassTimes& times = level.lateral_passes.emplace_back(
        traverse_times(passes[i].entry_length_mm, steady_travels_mm[i], feeds));  // t_i,f
    level.entry_time_min += times.entry_time_min;
    level.steady_time_min += times.steady_time_min;
    level.time_min += times.time_min;
  }
  return level;
}

}  // namespace

// E24-E41. Checks on fields alone come first, then the contours, then the pass counts; geometry
// runs last.
Result<MainTimeResult> compute_main_time(const MainTimeParams& params) {
  if (auto error = detail::check_width_of_cut(params)) {
    return *error;
  }
  Result<detail::Feeds> feeds = detail::compute_feeds(params);  // E30-E33
  if (!feeds.ok()) {
    return feeds.error();
  }
  std::optional<detail::Feeds> finish_feeds;
  if (params.finish) {
    Result<detail::Feeds> feeds_f = detail::compute_finish_feeds(params, feeds.value());  // E40
    if (!feeds_f.ok()) {
      return feeds_f.error();
    }
    finish_feeds = feeds_f.value();
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
  Result<std::vector<double>> depths = depth_levels(params);  // E25, E37, E39
  if (!depths.ok()) {
    return depths.error();
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
  result.depth_passes_mm = std::move(depths.value());

  const double r = params.cutter_diameter_mm / 2.0;  // r (E1)
  const std::vector<detail::LateralFrame> frames = detail::place_lateral_passes(
      N1.value(), B, detail::lateral_cut_mm(N1.value(), allowance, params.pass_split), r,
      params.offset_mm.value_or(0.0));    // E27, E38
  std::vector<double> steady_travels_mm;  // L_rx,i - L_vr,i
  steady_travels_mm.reserve(frames.size());
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
    steady_travels_mm.push_back(geometry.value().steady_travel_mm);
    entry_time_one_level += pass.entry_time_min;
    steady_time_one_level += pass.steady_time_min;
    time_one_level += pass.time_min;
  }

  // E35-E36: every roughing level repeats the same lateral passes; E41: the finishing level runs
  // them once more at its own feeds.
  const std::size_t roughing_levels = result.depth_passes_mm.size() - (params.finish ? 1 : 0);
  const double levels = static_cast<double>(roughing_levels);  // N2, or N2r with a finish
  result.main_time_min = levels * time_one_level;              // T_o
  result.entry_time_min = levels * entry_time_one_level;
  result.steady_time_min = levels * steady_time_one_level;
  if (finish_feeds) {
    result.finish = finish_level(result.depth_passes_mm.back(), *finish_feeds,
                                 result.lateral_passes, steady_travels_mm);
    result.main_time_min += result.finish->time_min;  // E41
    result.entry_time_min += result.finish->entry_time_min;
    result.steady_time_min += result.finish->steady_time_min;
  }
  if (!all_finite(result)) {
    return make_error(ErrorCode::not_converged, "the result is too large to represent");
  }
  return result;
}

}  // namespace cutcalc::domain::entry
