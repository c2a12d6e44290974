#pragma once
// The "v razvod" grooving cycle (spec grooving-cycle.md, K1-K23; paper 003, scheme Fig. 1a): a
// tool narrower than the groove by the shift X2 plunges radially and, every other revolution, moves
// by X2 along Z in the same block, alternately +Z and back; a dwell and a final shift by X2 at the
// bottom bring the groove to its width. Units: mm, mm/rev, m/min, rev/min, minutes, um for Rz.
// Scope: an external groove from Z = z_L to z_L + W; X values are diameters.

#include <optional>
#include <string_view>
#include <vector>

#include "domain/common/result.h"
#include "domain/grooving/revolution_time.h"
#include "domain/program/program_warning.h"
#include "domain/roughness/groove_wall.h"

namespace cutcalc::domain::grooving {

// The service's cap on the pattern's revolutions (section 5.1: one program block each).
inline constexpr double kMaxRevolutions = 20000;

struct GroovingCycleParams {
  double groove_width_mm = 0.0;              // W > 0
  double start_diameter_mm = 0.0;            // D0 > 0
  std::optional<double> bottom_diameter_mm;  // Db (exactly one of Db and h)
  std::optional<double> groove_depth_mm;     // h
  double groove_left_z_mm = 0.0;             // z_L, the groove's -Z wall
  std::optional<double> shift_mm;            // X2 (K3)
  std::optional<double> tool_width_mm;       // B (K3)
  double feed_per_rev_mm = 0.0;              // S0, requested radial feed
  SpindleMode spindle;                       // n, or v with n_max
  double nose_radius_mm = 0.0;               // rho
  double minor_edge_angle_deg = 0.0;         // phi1
  double dwell_revolutions = 1.0;            // n_d >= 0
  double approach_clearance_mm = 1.0;        // c > 0
  double rapid_mm_per_min = 10000.0;         // retract time only
};

enum class Side { left, right };  // z_L, or z_R = z_L + X2

// One pattern revolution k = 1..N (K10): from D_(k-1) to D_k, ending at `side`.
struct PatternBlock {
  double diameter_mm = 0.0;  // D_k
  Side side = Side::left;
  bool shifts = false;  // k even: radial and axial in one block at f_sh
};

struct GroovingCycleResult {
  double tool_width_mm = 0.0;                // B
  double shift_mm = 0.0;                     // X2
  double groove_depth_mm = 0.0;              // h
  double bottom_diameter_mm = 0.0;           // Db
  double approach_diameter_mm = 0.0;         // D_a (K2)
  double right_z_mm = 0.0;                   // z_R (K11)
  int revolutions = 0;                       // N (K7)
  int radial_revolutions = 0;                // N - floor(N/2)
  int shift_revolutions = 0;                 // floor(N/2)
  int shifts = 0;                            // floor(N/2) + 1, the final included
  double infeed_per_revolution_mm = 0.0;     // s (K8)
  double shift_feed_mm_per_rev = 0.0;        // f_sh (K10)
  double final_shift_revolutions = 0.0;      // X2/s
  double spindle_revolutions = 0.0;          // c/s + N + n_d + X2/s
  Side pattern_end_side = Side::left;        // K12
  Side end_side = Side::right;               // where the final shift ends
  double approach_time_min = 0.0;            // K17
  double plunge_time_min = 0.0;              // K18
  double shift_time_min = 0.0;               // K18
  double dwell_time_min = 0.0;               // K19
  double dwell_seconds = 0.0;                // n_d * 60 / n(Db)
  double final_shift_time_min = 0.0;         // K19
  double retract_time_min = 0.0;             // K20
  double cycle_time_min = 0.0;               // K20
  double spindle_speed_at_start_rpm = 0.0;   // n(D0)
  double spindle_speed_at_bottom_rpm = 0.0;  // n(Db)
  double chip_thickness_mm = 0.0;            // K22
  double side_chip_thickness_mm = 0.0;       // K22
  double wall_pitch_mm = 0.0;                // K21: 4 s
  double wall_rz_um = 0.0;                   // K21
  roughness::CrestBranch wall_rz_branch = roughness::CrestBranch::nose_arc;
  double plain_plunge_rz_um = 0.0;         // K21 at S = S0
  std::vector<PatternBlock> pattern;       // K9-K12, N blocks
  std::vector<program::Warning> warnings;  // K5, K23, in the order of section 3.7
};

// K1-K23. Errors: bottom_not_below_start (Db >= D0), groove_too_deep (2h >= D0), shift_too_wide
// (X2 >= W), tool_too_wide (B >= W), tool_and_shift_mismatch (K3), tool_not_wider_than_shift (K4),
// too_many_revolutions (N over kMaxRevolutions; limit).
Result<GroovingCycleResult> compute_grooving_cycle(const GroovingCycleParams& params);

// The Z of `side`.
double side_z_mm(const GroovingCycleParams& params, const GroovingCycleResult& cycle, Side side);

std::string_view side_name(Side side);

}  // namespace cutcalc::domain::grooving
