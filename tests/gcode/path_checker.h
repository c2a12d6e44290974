#pragma once
// Checks a program as LinuxCNC reads it (the canonical motions of rs274) against the exact centre
// path, independently of the generator (spec polygon-holes.md sections 5, 6 and 9): every point of
// every arc within tolerance + 0.0001 mm of the path and the path within that of the arcs, circle
// tangents continuous within 0.05 deg at every join, every loop closed at (0, e), Z down to
// -depth by ramps linear in path length, and optionally the F and C words.

#include <cstddef>
#include <string>
#include <vector>

#include "gcode/canon_parser.h"
#include "gcode/exact_path.h"

namespace cutcalc::test::gcode {

enum class FeedCheck { none, feed_per_rev, c_axis };

// What the program should contain (P22): `layers` layers of `loops_per_layer` loops of
// `blocks_per_loop` arcs, the first loop of each layer a ramp, plus one flat loop at -depth when
// loops_per_layer = 1.
struct ProgramLayout {
  int blocks_per_loop = 1;
  int layers = 1;
  int loops_per_layer = 1;
  double depth_mm = 0.0;
  double tolerance_mm = 0.001;
  FeedCheck feed_check = FeedCheck::none;
  double spindle_speed_rpm = 0.0;  // c_axis: F = rpm * feed_per_rev
  [[nodiscard]] int loops() const {
    return layers * loops_per_layer + (loops_per_layer == 1 ? 1 : 0);
  }
};

// The limits the checker enforces.
inline constexpr double kOutputResolutionMm = 0.0001;  // allowance for the 4-decimal output
inline constexpr double kMaxKinkDeg = 0.05;

struct PathCheckReport {
  std::size_t arcs = 0;
  std::size_t expected_arcs = 0;
  double max_deviation_mm = 0.0;     // arc points (LinuxCNC interpolation) -> exact path
  int worst_arc_line = 0;            // rs274 output line of the arc with the largest deviation
  double max_uncovered_mm = 0.0;     // exact path -> polyline of each loop's arcs
  double max_kink_deg = 0.0;         // circle tangents at the joins of consecutive arcs
  int worst_kink_line = 0;           // rs274 output line of the arc after the worst join
  double max_spiral_kink_deg = 0.0;  // the same with LinuxCNC's spiral tangents (information)
  double start_offset_mm = 0.0;      // first arc start -> (0, e)
  double max_closure_mm = 0.0;       // each loop's end -> the first arc's start
  double max_z_error_mm = 0.0;       // loop-end levels -k dz and the ramps' linear Z
  bool z_non_increasing = true;
  double final_z_mm = 0.0;
  double min_z_mm = 0.0;
  double printed_loop_length_mm = 0.0;  // L_p of the first loop (P23)
  double loop_length_spread_mm = 0.0;   // largest difference of L_p between loops
  double exact_loop_length_mm = 0.0;    // L (P10)
  double max_feed_error = 0.0;          // F against (N-1) L_p (P23), if checked
  bool feed_mode_ok = true;
  double max_c_error_deg = 0.0;  // C against -(180/pi) t of the nearest path point, if c_axis
  double c_tolerance_deg = 0.0;  // what the 4-decimal X Y allow for it
  std::vector<std::string> violations;  // empty: accepted
};

PathCheckReport check_program(const CanonProgram& program, const ExactCentrePath& path,
                              const ProgramLayout& layout);

}  // namespace cutcalc::test::gcode
