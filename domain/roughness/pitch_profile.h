#pragma once
// The wall profile over one pitch (spec roughness.md R.7, R9-R13; paper 003): which edges form
// the crest (R2-R5), the profile's two sides, its mean line, Ra and the material ratio, for
// phi1 > 0. Lengths in mm. Private to domain/roughness.

#include "domain/roughness/crest_branches.h"
#include "domain/roughness/groove_wall.h"

namespace cutcalc::domain::roughness::detail {

// One pitch, x from the previous corner (x = 0) to the current one (x = S); heights out of the
// material y(x) = rho - w(x), 0 at the corners, Rz at the crest (R9).
struct PitchProfile {
  double S = 0.0;    // S, pitch
  double rho = 0.0;  // rho, nose radius
  MinorEdgeAngle phi1;
  double Rz = 0.0;  // Rz (R1), the highest peak
  CrestBranch branch = CrestBranch::nose_arc;
  double u_c = 0.0;         // u_c, where the left side (previous leading arc) ends (R9)
  double y_left_end = 0.0;  // y(u_c-): Rz, or rho in branch C where the profile jumps to Rz
};

// R2-R5 and R9: the crest and the sides of the profile of pitch S (a limit value of R2 belongs to
// the lower branch).
PitchProfile pitch_profile(double S, double rho, const MinorEdgeAngle& phi1);

// R11: integral of the nose-arc height u^2 / (rho + sqrt(rho^2 - u^2)) over [0, a], 0 <= a <= rho.
double nose_arc_area(double a, double rho);

// R10: height ybar of the mean line above the corners.
double mean_line_height(const PitchProfile& profile);

// R12: arithmetic mean deviation Ra of the profile from its mean line, mm.
double arithmetic_mean_deviation(const PitchProfile& profile);

// R13: material ratio Rmr(c) at depth c >= 0 below the highest peak, in [0, 1].
double material_ratio(const PitchProfile& profile, double c);

}  // namespace cutcalc::domain::roughness::detail
