#pragma once
// A flat (or 2..12 equal flats) milled on a lathe by C-axis steps with X following (spec
// lathe-flat.md, F1-F21; paper 000, Figs. 12-13): geometry, step table, flatness error and the N
// a tolerance needs, layers, blocks, the block-rate feed limit and the time. Units: mm, mm/min,
// ms, minutes; angles in degrees in the answer.

#include <optional>
#include <vector>

#include "domain/common/result.h"
#include "domain/lathe_flat/flat_geometry.h"
#include "domain/program/program_warning.h"

namespace cutcalc::domain::lathe_flat {

struct LatheFlatParams {
  double part_diameter_mm = 0.0;                // D
  std::optional<double> flat_depth_mm;          // t   (exactly one of t, b, d, s)
  std::optional<double> flat_width_mm;          // b
  std::optional<double> axis_distance_mm;       // d
  std::optional<double> across_flats_mm;        // s = 2d, flats >= 2
  int flats = 1;                                // m, 1..12
  double tool_radius_mm = 0.0;                  // R >= 0 (0: a point tool)
  std::optional<int> steps;                     // N, 1..1000
  std::optional<double> flatness_tolerance_mm;  // tol: gives N by F16 without `steps`
  std::optional<double> layer_depth_mm;         // a; default t (one layer)
  double feed_mm_per_min = 0.0;                 // f, relative to the part along the flat
  double block_time_ms = 2.0;                   // t_b (paper)
  double clearance_mm = 1.0;                    // c (F18)
  double z_mm = 0.0;                            // the cross-section the program works in
};

struct LatheFlatResult {
  double axis_distance_mm = 0.0;                   // d (F1)
  double flat_depth_mm = 0.0;                      // t
  double flat_width_mm = 0.0;                      // b (F3)
  double face_width_mm = 0.0;                      // w (F4)
  double across_flats_mm = 0.0;                    // 2d
  double engagement_half_angle_deg = 0.0;          // alpha_e (F2)
  bool sharp_corners = false;                      // F4
  int steps = 0;                                   // N used
  std::optional<int> steps_for_tolerance;          // F16, with a tolerance
  int layers = 0;                                  // L (F17)
  std::vector<double> layer_depths_mm;             // t_j
  double x_travel_mm = 0.0;                        // F8
  std::vector<StepRow> steps_table;                // final layer, flat 1
  double flatness_error_mm = 0.0;                  // F14
  double flatness_error_estimate_mm = 0.0;         // F15
  int cut_blocks = 0;                              // F19
  double shortest_block_mm = 0.0;                  // F20
  double max_feed_by_block_rate_mm_per_min = 0.0;  // F21
  double cut_time_min = 0.0;                       // F19
  double approach_time_min = 0.0;                  // F19
  double machining_time_min = 0.0;                 // F19
  double clear_x_mm = 0.0;                         // X_c (F18), a radius
  std::vector<FlatSection> layer_sections;         // the flat of each layer (d_j), for the program
  std::vector<program::Warning> warnings;          // F21, flatness_over_tolerance
};

// F1-F21. Errors: flat_outside_part (t >= R2, d >= R2, s >= D or b >= D: the given one),
// flat_too_small (a flat or layer so shallow against the part that d rounds to R2 in doubles),
// tolerance_unmet (no N <= 1000 meets it), too_many_cut_blocks (over program::kMaxProgramBlocks
// cutting blocks; limit).
Result<LatheFlatResult> compute_lathe_flat(const LatheFlatParams& params);

}  // namespace cutcalc::domain::lathe_flat
