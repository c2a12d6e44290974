#pragma once
// G-code for an N-faceted hole cut by a rolling rotor tool, with the predicted hole
// (spec polygon-holes.md P1-P34; paper 004, corrected; block-rate limit from paper 000).
// Units: mm, rev/min, ms, degrees in the program. Inputs are range-checked by the caller (each
// field on its own, spec section 10); this function checks what depends on several inputs.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "domain/common/result.h"
#include "domain/common/text_source.h"
#include "domain/program/program_options.h"

namespace cutcalc::domain::polygon {

namespace detail {
struct PolygonProgram;
struct OvercutPrediction;
}  // namespace detail

inline constexpr int kMaxBiarcsPerEllipseArc = 1000;  // P21: else tolerance_unreachable

enum class Synchronization {
  feed_per_rev,  // G95, F = feed per spindle revolution (the paper's way); phase not locked
  c_axis,        // spindle as rotary axis C: the exact rotor phase in C words on every arc
};

struct PolygonHoleParams {
  int faces = 4;                       // N, 3..12
  double inscribed_diameter_mm = 0.0;  // d >= 1
  double depth_mm = 0.0;               // > 0
  double step_down_mm = 0.0;           // largest step per layer, > 0
  double spindle_speed_rpm = 0.0;      // > 0
  double tolerance_mm = 0.001;         // arc-fit tolerance, 0.0001..0.1
  Synchronization synchronization = Synchronization::feed_per_rev;
  std::optional<int> loops_per_layer;  // 1..100; default N - 1 (one spindle revolution)
  double safe_z_mm = 5.0;              // > 0
  double block_time_ms = 2.0;          // the control's block processing time, > 0
  // The final G0 Z's rate for rapid_time_min (P34); the pass program's default.
  double rapid_mm_per_min = program::ProgramOptions{}.rapid_mm_per_min;  // > 0
  // The `program` object (programs.md section 2): absent, today's program byte for byte.
  std::optional<program::ProgramOptions> program;
  program::MachineLimits machine;  // limits that turn into warnings (programs.md section 5)
};

// P28: one flank arc of the rotor between corners 0 and 1 (rotor frame, pose t = 0, corner 0 at
// (0, -r)); flank v is it turned by 360 v / M degrees.
struct RotorFlankArc {
  double radius_mm = 0.0;    // R_m (P12)
  double centre_x_mm = 0.0;  // O_{0,m}
  double centre_y_mm = 0.0;
  double start_angle_deg = 0.0;  // outward normal range theta_0 + m delta ..
  double end_angle_deg = 0.0;    // .. theta_0 + (m + 1) delta
};

// P28-P30: the rotor as a drawing for grinding it and checking the mating part, mm and degrees.
struct RotorDimensions {
  int corners = 0;                         // M = N - 1
  double corner_circle_diameter_mm = 0.0;  // 2 r (P4)
  double corner_angle_deg = 0.0;           // 180 - 2 delta
  std::vector<RotorFlankArc> flank_arcs;   // m = 1..N-2
  double width_min_mm = 0.0;               // P29: caliper width, min over the directions
  double width_max_mm = 0.0;               // P29: max
  double neck_diameter_max_mm = 0.0;       // P30: the largest neck that clears the hole
};

// P32-P34: the machining time of the program, min (no acceleration, tool change, spindle start,
// first positioning move).
struct MachiningTime {
  double working_min = 0.0;  // P32: the loops
  double plunge_min = 0.0;   // P33: G1 Z0 from the safe height
  double rapid_min = 0.0;    // P34: the final G0 Z
  double cycle_min = 0.0;    // P34: the sum
};

struct PolygonHoleResult {
  // Section 5's program, LF line ends: its text is written as it is read (open_program_text).
  std::shared_ptr<const detail::PolygonProgram> program;
  int blocks_per_loop = 0;             // P21
  double loop_length_mm = 0.0;         // L_p (P23)
  double feed_per_rev_mm = 0.0;        // (N - 1) L_p (P23)
  double eccentricity_mm = 0.0;        // e (P5)
  double max_path_deviation_mm = 0.0;  // P20
  // P24-P26, kept from the fit for predicted_overcut_mm(): the prediction samples every block, and
  // no program text needs it (a JSON answer writes it after the program).
  std::shared_ptr<const detail::OvercutPrediction> overcut;
  double uncut_corner_area_mm2 = 0.0;              // P17, all N corners
  double corner_gap_mm = 0.0;                      // g (P15)
  double max_feed_by_block_rate_mm_per_min = 0.0;  // P27
  RotorDimensions rotor;                           // P28-P30
  double corner_radius_mm = 0.0;                   // rho_c (P31 = P16)
  MachiningTime time;                              // P32-P34
  std::vector<program::Warning> warnings;          // programs.md section 5 order, then sections 7-8
  std::string file_name;  // polygon-hole-N{N}-d{d with 4 decimals}.ngc, or the dialect's
  // With a `program` object: P20 on the arcs as printed (programs.md section 4), mm; the
  // warnings are then comment lines of the program itself.
  std::optional<double> printed_path_deviation_mm;
};

// P1-P34. Errors: tolerance_unreachable (m > 1000 biarcs needed), program_too_large (more than
// program::kMaxProgramBlocks arc blocks), not_converged (a numerical procedure failed: a bug).
Result<PolygonHoleResult> generate_polygon_hole(const PolygonHoleParams& params);

// P26: the largest overcut predicted for the programmed motion, mm (about 7 ms for the largest
// program; microseconds for a typical one).
double predicted_overcut_mm(const PolygonHoleResult& result);

// The program's text, written as it is read. `warning_comments`: each warning written as a comment
// line `(WARNING {code}: {detail})` after the first comment line, for the plain-text answer where
// the JSON warnings are not seen (a dialect program has them in its comment block already).
std::unique_ptr<TextSource> open_program_text(const PolygonHoleResult& result,
                                              bool warning_comments);

// The whole text of open_program_text.
std::string program_text(const PolygonHoleResult& result, bool warning_comments = false);

}  // namespace cutcalc::domain::polygon
