#pragma once
// Main (machine) time of a face-milling setup over N1 lateral x N2 depth passes, with a reduced
// feed on each entry section (spec entry-and-main-time.md E24-E36; paper 002). Units: millimetres,
// rev/min, mm/min, m/min for the cutting speed, minutes for times.

#include <optional>
#include <variant>
#include <vector>

#include "domain/common/result.h"
#include "domain/entry/contour.h"
#include "domain/entry/entry_length.h"

namespace cutcalc::domain::entry {

// A service guard, not part of the model: each pass becomes an element of the response, so an
// allowance divided into millions of cuts is refused (too_many_*_passes) instead of filling memory.
inline constexpr std::size_t kMaxPassCount = 10000;

struct SpindleSpeed {
  double rpm = 0.0;  // n
};
struct CuttingSpeed {
  double m_per_min = 0.0;  // v; n = 1000 v / (pi D) (E30)
};

struct EntryFeedFactor {
  double factor = 0.5;  // f: S_m1 = f S_m2 (E33)
};
struct EntryFeedPerTooth {
  double mm = 0.0;  // S_z1: S_m1 = n z S_z1 (E33)
};

struct Allowance {
  double width_mm = 0.0;         // H1
  double width_of_cut_mm = 0.0;  // t
  double depth_mm = 0.0;         // H
  double depth_of_cut_mm = 0.0;  // t0
};

// E37: how an allowance is divided into passes of at most one cut each.
enum class PassSplit {
  last_smaller,  // E25: full cuts, then the remainder (default)
  equal,         // E37: N equal passes (the paper's recommendation, section 7.1)
};

// E39: the last depth level as a finishing level with its own depth, feed and speed.
struct Finish {
  double depth_of_cut_mm = 0.0;    // t_f
  double feed_per_tooth_mm = 0.0;  // S_zf
  // n_f (E40); absent: the roughing spindle speed n.
  std::optional<std::variant<SpindleSpeed, CuttingSpeed>> speed;
};

struct MainTimeParams {
  double cutter_diameter_mm = 0.0;  // D
  int teeth = 1;                    // z
  std::variant<SpindleSpeed, CuttingSpeed> speed;
  double feed_per_tooth_mm = 0.0;  // S_z
  std::variant<EntryFeedFactor, EntryFeedPerTooth> entry_feed;
  double length_mm = 0.0;      // L
  double extra_path_mm = 0.0;  // L1
  double approach_mm = 2.0;    // L_pod
  double overrun_mm = 2.0;     // L_per
  Contour entry;
  Contour exit;
  std::optional<double> offset_mm;  // K; only with one lateral pass
  Allowance allowance;
  PassSplit pass_split = PassSplit::last_smaller;  // E37; applies to widths and depths
  std::optional<Finish> finish;                    // E39
};

struct LateralPass {
  double width_mm = 0.0;              // W_i: engaged width in steady cutting
  double axis_y_mm = 0.0;             // Y_ax,i in the part frame (from the side edge, E26-E27)
  double offset_mm = 0.0;             // K_i from the strip's centre (E28)
  double strip_width_mm = 0.0;        // B_i
  double engagement_length_mm = 0.0;  // L_vr1,i
  double entry_length_mm = 0.0;       // L_vr,i
  Position start;                     // X_n, Y_n in the strip's entry frame
  Position end;                       // X_k, Y_k in the strip's exit frame
  double working_stroke_mm = 0.0;     // L_rx,i
  double entry_time_min = 0.0;        // t_e,i for one traverse (E34)
  double steady_time_min = 0.0;       // t_s,i for one traverse (E34)
  double time_min = 0.0;              // t_i (E34)
  // Not in the answer: Y_(i-1), the side of the strip still uncut (E27; program coordinates).
  double lower_boundary_mm = 0.0;
};

// One traverse of a lateral pass at the finishing level's feeds (E41: t_i,f).
struct PassTimes {
  double entry_time_min = 0.0;   // L_vr,i / S_m1f
  double steady_time_min = 0.0;  // (L_rx,i - L_vr,i) / S_m2f
  double time_min = 0.0;         // t_i,f
};

// The finishing level (E39-E41): one traverse of every lateral pass at its own feeds.
struct FinishLevel {
  double depth_mm = 0.0;               // t_f
  double spindle_speed_rpm = 0.0;      // n_f (E40)
  double feed_per_rev_mm = 0.0;        // z S_zf
  double feed_mm_per_min = 0.0;        // S_m2f (E40)
  double entry_feed_mm_per_min = 0.0;  // S_m1f (E40)
  std::vector<PassTimes> lateral_passes;
  double entry_time_min = 0.0;   // sum_i L_vr,i / S_m1f
  double steady_time_min = 0.0;  // sum_i (L_rx,i - L_vr,i) / S_m2f
  double time_min = 0.0;         // sum_i t_i,f
};

struct MainTimeResult {
  double spindle_speed_rpm = 0.0;           // n (E30)
  double feed_per_rev_mm = 0.0;             // S_o (E31)
  double feed_mm_per_min = 0.0;             // S_m2 (E32)
  double entry_feed_mm_per_min = 0.0;       // S_m1 (E33)
  std::vector<double> depth_passes_mm;      // E25
  std::vector<LateralPass> lateral_passes;  // times: one roughing traverse
  std::optional<FinishLevel> finish;        // only with params.finish: the last depth level
  double main_time_min = 0.0;               // T_o (E35, E41)
  double entry_time_min = 0.0;              // E36
  double steady_time_min = 0.0;             // E36
};

// E24-E41. Errors: every error of compute_entry_length, plus offset_with_several_passes,
// allowance_wider_than_part, allowance_not_full_width, width_of_cut_exceeds_diameter,
// entry_feed_exceeds_feed (also against the finishing S_zf), too_many_lateral_passes,
// too_many_depth_passes, finish_depth_not_below_depth.
Result<MainTimeResult> compute_main_time(const MainTimeParams& params);

}  // namespace cutcalc::domain::entry
