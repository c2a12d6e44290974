#pragma once
// The G-code text of spec polygon-holes.md section 5: number format, the printed loop (P23) and
// the program skeleton with layers and helical ramps (P22). Private to domain/polygon.

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "domain/common/text_source.h"
#include "domain/polygon/biarc_fit.h"
#include "domain/polygon/polygon_hole.h"
#include "domain/program/dialect_writer.h"
#include "domain/program/program_options.h"

namespace cutcalc::domain::polygon::detail {

// Today's program (no `program` object) prints its numbers with 4 decimals, in mm.
inline constexpr int kPlainDecimals = 4;

// How the program prints its numbers: today's program kPlainDecimals in mm; with a `program`
// object `decimals` in the program's units (programs.md section 4).
struct NumberFormat {
  int decimals = kPlainDecimals;
  double units_per_mm = 1.0;                              // 1 / 25.4 for inch
  [[nodiscard]] std::string operator()(double mm) const;  // a length or feed given in mm
};

// One arc block of a loop as printed (the same in every loop), with the unrounded rotor
// rotation and fitted path length at its end (mm).
struct PrintedBlock {
  std::string X;
  std::string Y;
  std::string I;
  std::string J;
  double t_end = 0.0;
  double s_end = 0.0;
};

struct PrintedLoop {
  std::string start_X;  // the loop start (0, e), printed
  std::string start_Y;
  std::vector<PrintedBlock> blocks;
  double printed_length = 0.0;  // L_p (P23)
  double fitted_length = 0.0;   // L_u: the unrounded arcs (mm)
};

// P23: the blocks of one loop (`scale` = d turns the unit-diameter blocks into mm) printed with
// `format`, I and J from the unrounded centre minus the unrounded start (normative), and L_p from
// the printed numbers as LinuxCNC interpolates them, in mm.
PrintedLoop print_loop(const std::vector<LoopBlock>& blocks, double scale,
                       const NumberFormat& format = {});

// P22: the layers: n = ceil(depth / step - 1e-9) (at least 1), dz = depth / n.
struct Layers {
  double n = 1.0;  // a count, kept in double until the caller checked the program size
  double dz = 0.0;
};
Layers split_depth(double depth_mm, double step_down_mm);

// Everything the program text needs besides the loop.
struct ProgramLayout {
  int N = 4;
  double d_mm = 0.0;
  double a_mm = 0.0;
  double r_mm = 0.0;
  double e_mm = 0.0;
  double exact_loop_length_mm = 0.0;  // L (P10), for the comments
  double tolerance_mm = 0.0;
  double deviation_mm = 0.0;
  double depth_mm = 0.0;
  double step_down_mm = 0.0;
  int layers = 1;
  double dz_mm = 0.0;
  int loops_per_layer = 1;
  double safe_z_mm = 5.0;
  double spindle_speed_rpm = 0.0;
  Synchronization synchronization = Synchronization::feed_per_rev;
  double feed_per_rev_mm = 0.0;  // (N-1) L_p
};

// How the body is written: today's words and numbers, or a dialect's (programs.md section 2).
struct BodyStyle {
  NumberFormat fmt;
  const program::DialectWords* words = nullptr;
  std::string spindle_speed;                // the S word's number
  bool ramp_feed_along_projection = false;  // fanuc: F along the arc projected on XY
  program::Coolant coolant = program::Coolant::off;
};

// A program as its text is made: everything before the body (`head`), the layout and the printed
// loop the body repeats, and the end after it (`tail`). Read by open_program.
struct PolygonProgram {
  std::string head;
  ProgramLayout layout;
  PrintedLoop loop;
  BodyStyle style;
  std::string tail;
  [[nodiscard]] std::size_t held_bytes() const;
};

// The text of `program` with `head` in place of its own (warning lines added), written as it is
// read: the body of section 5, P22 (layers, ramps with Z linear in unrounded path length), P23 (F
// words) and the C words of the c_axis mode, from S M3 (c_axis: G0 X Y C0) with [M8|M7] through M5
// (c_axis: the last G0 Z) and [M9], then the tail. A fanuc ramp loop takes the flat F: it applies F
// along the arc's projection on the plane.
std::unique_ptr<TextSource> open_program(std::shared_ptr<const PolygonProgram> program,
                                         std::string head);

// Today's comment lines (their text, numbers in mm), in order; `ramp_feed_along_projection`: the
// ramp loops take the flat F (fanuc).
std::vector<std::string> program_comments(const ProgramLayout& layout, const PrintedLoop& loop,
                                          bool ramp_feed_along_projection = false);

// Section 5's program: today's (no `program` object), with today's comments.
std::shared_ptr<const PolygonProgram> plain_program(const ProgramLayout& layout,
                                                    const PrintedLoop& loop);

// The program in a dialect (programs.md section 2, polygon): the dialect's header with today's
// comments (`comments`: warnings after the first), [tool change] G0 [G43] Z{safe} [H], the body,
// the dialect's end. `loop` printed with the options' NumberFormat.
std::shared_ptr<const PolygonProgram> dialect_program(const ProgramLayout& layout,
                                                      const PrintedLoop& loop,
                                                      const std::vector<std::string>& comments,
                                                      const program::ProgramOptions& options);

// P22: the number of arc blocks of the program as counted in section 10.
double program_arc_blocks(double layers, int loops_per_layer, std::size_t blocks_per_loop);

}  // namespace cutcalc::domain::polygon::detail
