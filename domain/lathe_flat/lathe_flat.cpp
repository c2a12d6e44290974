#include "domain/lathe_flat/lathe_flat.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "domain/common/numeric.h"
#include "domain/lathe_flat/flatness.h"
#include "domain/program/program_options.h"
#include "domain/program/program_size.h"

namespace cutcalc::domain::lathe_flat {
namespace {

using program::number_text;
using program::Warning;
using program::WarningCode;

// F1: d from whichever of t, b, d, s was given; error when it is not inside the part.
Result<double> axis_distance(const LatheFlatParams& p) {
  const double r2 = p.part_diameter_mm / 2.0;
  if (p.flat_depth_mm) {
    if (*p.flat_depth_mm >= r2) return make_error(ErrorCode::flat_outside_part, "t >= R2");
    return r2 - *p.flat_depth_mm;
  }
  if (p.flat_width_mm) {
    if (*p.flat_width_mm >= p.part_diameter_mm) {
      return make_error(ErrorCode::flat_outside_part, "b >= D");
    }
    const double half = *p.flat_width_mm / 2.0;
    return std::sqrt((r2 - half) * (r2 + half));
  }
  if (p.across_flats_mm) {
    if (*p.across_flats_mm >= p.part_diameter_mm) {
      return make_error(ErrorCode::flat_outside_part, "s >= D");
    }
    return *p.across_flats_mm / 2.0;
  }
  const double d = p.axis_distance_mm.value_or(0.0);
  if (d >= r2) return make_error(ErrorCode::flat_outside_part, "d >= R2");
  return d;
}

// F17: L = ceil(t/a - 1e-9), at least 1 (ceil_count); a double, since a very thin layer gives more
// layers than an int holds (the block cap refuses those before any list is made).
double layer_count(double t, const std::optional<double>& layer_depth_mm) {
  return ceil_count(t / layer_depth_mm.value_or(t));
}

// F17: L equal layers, t_j = j t / L, the last exactly t.
std::vector<double> layer_depths(double t, int layers) {
  std::vector<double> depths;
  depths.reserve(static_cast<std::size_t>(layers));
  for (int j = 1; j <= layers; ++j) depths.push_back(j == layers ? t : j * t / layers);
  return depths;
}

}  // namespace

Result<LatheFlatResult> compute_lathe_flat(const LatheFlatParams& p) {
  const auto d = axis_distance(p);
  if (!d.ok()) return d.error();
  const double r2 = p.part_diameter_mm / 2.0;
  LatheFlatResult r;
  r.axis_distance_mm = d.value();
  // t = R2 - d loses every digit when the flat is tiny against the part: t as given, or from b.
  if (p.flat_depth_mm) {
    r.flat_depth_mm = *p.flat_depth_mm;
  } else if (p.flat_width_mm) {
    const double half = *p.flat_width_mm / 2.0;
    r.flat_depth_mm = half * half / (r2 + r.axis_distance_mm);
  } else {
    r.flat_depth_mm = r2 - r.axis_distance_mm;
  }
  r.across_flats_mm = 2.0 * r.axis_distance_mm;
  const FlatSection final_flat{r2, r.axis_distance_mm, p.tool_radius_mm, r.flat_depth_mm};
  const double alpha_e = engagement_half_angle_rad(final_flat);  // F2
  if (!(r.flat_depth_mm > 0.0) || !(alpha_e > 0.0)) {
    return make_error(ErrorCode::flat_too_small, "d rounds to R2");
  }
  r.engagement_half_angle_deg = rad_times_180_over_pi(alpha_e);
  r.flat_width_mm = flat_width_mm(final_flat);  // F3
  r.face_width_mm = r.flat_width_mm;            // F4
  if (p.flats >= 3) {
    const double half_pitch = std::numbers::pi / p.flats;
    r.face_width_mm = std::min(r.flat_width_mm, 2.0 * r.axis_distance_mm * std::tan(half_pitch));
    r.sharp_corners = alpha_e >= half_pitch;
  }

  if (p.flatness_tolerance_mm) {  // F16
    r.steps_for_tolerance =
        steps_for_tolerance(final_flat, r.face_width_mm, *p.flatness_tolerance_mm);
    if (!r.steps_for_tolerance) return make_error(ErrorCode::tolerance_unmet);
  }
  r.steps = p.steps ? *p.steps : r.steps_for_tolerance.value_or(1);
  const int n = r.steps;

  const double layers = layer_count(r.flat_depth_mm, p.layer_depth_mm);
  const double blocks = 2.0 * n * p.flats * layers;  // F19
  if (blocks > program::kMaxProgramBlocks)
    return make_limit_error(ErrorCode::too_many_cut_blocks, program::kMaxProgramBlocks);
  r.cut_blocks = static_cast<int>(blocks);
  r.layers = static_cast<int>(layers);
  r.layer_depths_mm = layer_depths(r.flat_depth_mm, r.layers);

  for (const double t_j : r.layer_depths_mm) {
    r.layer_sections.push_back({r2, r2 - t_j, p.tool_radius_mm, t_j});
  }
  // F18: the start X grows with depth, so the final layer's is the largest.
  r.clear_x_mm = tool_radius_position_mm(final_flat, alpha_e) + p.clearance_mm;
  r.shortest_block_mm = std::numeric_limits<double>::infinity();
  for (const FlatSection& layer : r.layer_sections) {
    const double a_e = engagement_half_angle_rad(layer);
    const double reach = layer.axis_distance_mm + layer.tool_radius_mm;
    r.cut_time_min += p.flats * 2.0 * reach * std::tan(a_e) / p.feed_mm_per_min;  // F19
    r.approach_time_min +=
        p.flats * (r.clear_x_mm - tool_radius_position_mm(layer, a_e)) / p.feed_mm_per_min;
    r.shortest_block_mm = std::min(r.shortest_block_mm, reach * std::tan(a_e / n));  // F20
  }
  // Each layer's middle block is its shortest (F20): a zero one would be an infinite G93 F.
  if (!(r.shortest_block_mm > 0.0))
    return make_error(ErrorCode::flat_too_small, "a layer's d rounds to R2");
  r.machining_time_min = r.cut_time_min + r.approach_time_min;
  r.max_feed_by_block_rate_mm_per_min = 60000.0 * r.shortest_block_mm / p.block_time_ms;  // F21
  r.x_travel_mm = tool_radius_position_mm(final_flat, alpha_e) -
                  (final_flat.axis_distance_mm + final_flat.tool_radius_mm);  // F8
  r.steps_table = step_table(final_flat, n);
  r.flatness_error_mm = flatness_error_mm(final_flat, r.face_width_mm, n);  // F14
  r.flatness_error_estimate_mm = flatness_error_estimate_mm(final_flat, n);

  if (p.feed_mm_per_min > r.max_feed_by_block_rate_mm_per_min) {
    r.warnings.push_back({WarningCode::feed_exceeds_block_rate,
                          "feed " + number_text(p.feed_mm_per_min) +
                              " mm/min is above the block-rate limit " +
                              number_text(r.max_feed_by_block_rate_mm_per_min) + " mm/min (" +
                              number_text(p.block_time_ms) + " ms per block)"});
  }
  if (p.steps && p.flatness_tolerance_mm && r.flatness_error_mm > *p.flatness_tolerance_mm) {
    r.warnings.push_back({WarningCode::flatness_over_tolerance,
                          "the flatness error " + number_text(r.flatness_error_mm * 1000.0) +
                              " um of " + std::to_string(n) + " steps is above the tolerance; " +
                              std::to_string(*r.steps_for_tolerance) + " steps meet it"});
  }
  return r;
}

}  // namespace cutcalc::domain::lathe_flat
