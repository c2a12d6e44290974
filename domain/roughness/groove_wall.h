#pragma once
// Theoretical crest height Rz_p and arithmetic mean roughness Ra on a groove side wall left by a
// grooving tool's corner (spec roughness.md part R, R1-R8, and R.7, R9-R12; paper 003). Units: mm
// inside, Rz in micrometres, degrees. Inputs are range-checked by the caller; this function checks
// what depends on several inputs.

#include <optional>

#include "domain/common/result.h"

namespace cutcalc::domain::roughness {

struct GrooveWallParams {
  double feed_mm = 0.0;                // S, pitch between successive corner positions, > 0
  double nose_radius_mm = 0.0;         // rho > 0
  double minor_edge_angle_deg = 0.0;   // phi1, 0 <= phi1 < 90
  std::optional<double> target_rz_um;  // optional target crest height, > 0
};

enum class CrestBranch {
  nose_arc,                  // R3: between two nose arcs
  nose_arc_and_minor_edge,   // R4: previous nose arc meets the current minor edge (paper eq. 6)
  minor_edge_and_main_edge,  // R5: current minor edge meets the previous main edge
};

struct GrooveWallResult {
  double rz_um = 0.0;  // Rz_p (R1)
  double ra_um = 0.0;  // Ra of the profile over one pitch (R12); 0 for phi1 = 0
  CrestBranch branch = CrestBranch::nose_arc;
  std::optional<double> max_feed_mm;  // largest S with Rz(S) <= target (R8), with a target only
};

// R1-R12. Errors: target_needs_minor_edge_angle (a target with phi1 = 0).
Result<GrooveWallResult> compute_groove_wall_roughness(const GrooveWallParams& params);

}  // namespace cutcalc::domain::roughness
