#pragma once
// The G-code text of spec polygon-holes.md section 5: number format, the printed loop (P23) and
// the program skeleton with layers and helical ramps (P22). Private to domain/polygon.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "domain/polygon/biarc_fit.h"
#include "domain/polygon/polygon_hole.h"

namespace cutcalc::domain::polygon::detail {

// printf("%.4f"), with -0.0000 written 0.0000.
std::string fmt4(double value);

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

// P23: the blocks of one loop in mm (`scale` = d turns the unit-diameter blocks into mm), I and J
// from the unrounded centre minus the unrounded start (normative), and L_p from the printed
// numbers as LinuxCNC interpolates them.
PrintedLoop print_loop(const std::vector<LoopBlock>& blocks, double scale);

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

// Section 5 (skeleton), P22 (layers, ramps with Z linear in unrounded path length), P23 (F
// words), and the C words of the c_axis mode.
std::string write_program(const ProgramLayout& layout, const PrintedLoop& loop);

// P22: the number of arc blocks of the program as counted in section 10.
double program_arc_blocks(double layers, int loops_per_layer, std::size_t blocks_per_loop);

}  // namespace cutcalc::domain::polygon::detail
