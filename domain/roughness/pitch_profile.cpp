// R9-R13 of spec roughness.md R.7 (paper 003): Ra and the material ratio in closed form from the
// areas under the two sides of one pitch, the crossings of a level found by inverting each side.

#include "domain/roughness/pitch_profile.h"

#include <algorithm>
#include <cmath>

namespace cutcalc::domain::roughness::detail {

namespace {

// th - sin(th): its series below 0.1 rad, where the difference would lose the leading digits
// (R11).
double theta_minus_sine(double th) {
  if (th < 0.1) {
    const double th2 = th * th;
    return th * th2 * (1.0 / 6.0 - th2 * (1.0 / 120.0 - th2 * (1.0 / 5040.0 - th2 / 362880.0)));
  }
  return th - std::sin(th);
}

// The abscissa where a nose arc reaches height y <= rho: u = sqrt(y (2 rho - y)).
double nose_arc_abscissa(double y, double rho) {
  return std::sqrt(std::max(y, 0.0)) * std::sqrt(std::max(2.0 * rho - y, 0.0));
}

// Height of the minor edge above the corner level at v = 0, negated: the line is
// y = v tan(phi1) - minor_edge_offset (R9), the arc joins it at v_a = rho sin(phi1).
double minor_edge_offset(double rho, const MinorEdgeAngle& phi1) {
  return rho * phi1.two_sin_sq_half / phi1.cos_phi1;
}

// R11: I_R(v), the area under the right side (current trailing arc, then the minor edge).
double right_side_area(const PitchProfile& p, double v) {
  const double v_a = p.rho * p.phi1.sin_phi1;  // v_a
  if (v <= v_a) {
    return nose_arc_area(v, p.rho);
  }
  return nose_arc_area(v_a, p.rho) + p.phi1.tan_phi1 * (v - v_a) * (v + v_a) / 2.0 -
         minor_edge_offset(p.rho, p.phi1) * (v - v_a);
}

// u(y): where the left side reaches height y, within [0, u_c].
double left_side_abscissa(const PitchProfile& p, double y) {
  return std::min(nose_arc_abscissa(y, p.rho), p.u_c);
}

// v(y): where the right side reaches height y, within [0, S - u_c]; the arc below
// y_a = 2 rho sin^2(phi1/2), the minor edge above (R12).
double right_side_abscissa(const PitchProfile& p, double y) {
  const double y_a = p.rho * p.phi1.two_sin_sq_half;  // y_a, where the arc meets the edge
  const double v = y <= y_a ? nose_arc_abscissa(y, p.rho)
                            : (y + minor_edge_offset(p.rho, p.phi1)) / p.phi1.tan_phi1;
  return std::min(v, p.S - p.u_c);
}

}  // namespace

// R2-R5, R9
PitchProfile pitch_profile(double S, double rho, const MinorEdgeAngle& phi1) {
  const BranchLimits limits = branch_limits(rho, phi1);
  PitchProfile p;
  p.S = S;
  p.rho = rho;
  p.phi1 = phi1;
  if (S <= limits.S_AB) {
    p.Rz = crest_height_nose_arc(S, rho);
    p.branch = CrestBranch::nose_arc;
    p.u_c = S / 2.0;
    p.y_left_end = p.Rz;
  } else if (S <= limits.S_BC) {
    p.Rz = crest_height_nose_arc_and_minor_edge(S, rho, phi1, limits);
    p.branch = CrestBranch::nose_arc_and_minor_edge;
    // sqrt(rho^2 - z_c^2) with z_c = rho - Rz, written without the cancellation.
    p.u_c = std::min(nose_arc_abscissa(p.Rz, rho), rho);
    p.y_left_end = p.Rz;
  } else {
    p.Rz = crest_height_minor_edge_and_main_edge(S, rho, phi1, limits);
    p.branch = CrestBranch::minor_edge_and_main_edge;
    p.u_c = rho;  // the previous main edge: the left side ends at y = rho, then jumps to Rz
    p.y_left_end = rho;
  }
  return p;
}

// R11: rho^2 (sin th sin^2(th/2) - (th - sin th)/2), th = asin(a/rho).
double nose_arc_area(double a, double rho) {
  const double th = std::asin(std::clamp(a / rho, 0.0, 1.0));  // th
  const double sin_half = std::sin(th / 2.0);
  return rho * rho * (std::sin(th) * sin_half * sin_half - theta_minus_sine(th) / 2.0);
}

// R10
double mean_line_height(const PitchProfile& p) {
  return (nose_arc_area(p.u_c, p.rho) + right_side_area(p, p.S - p.u_c)) / p.S;
}

// R12: the profile rises from each corner to the peak, so it lies below its mean line on
// [0, u_l] and [S - v_r, S] only; the deviations above and below balance, hence twice the area
// between the mean line and the profile below it.
double arithmetic_mean_deviation(const PitchProfile& profile) {
  // The areas grow as S^2: evaluated on the profile scaled by a power of two near max(S, rho)
  // (exact, the same branch), so that no area overflows where Rz and Ra themselves do not.
  const double scale = std::ldexp(1.0, std::ilogb(std::max(profile.S, profile.rho)));
  const PitchProfile p = pitch_profile(profile.S / scale, profile.rho / scale, profile.phi1);
  const double ybar = mean_line_height(p);  // ybar
  const double u_l = ybar < p.y_left_end ? left_side_abscissa(p, ybar) : p.u_c;
  const double v_r = right_side_abscissa(p, ybar);
  const double below = ybar * (u_l + v_r) - nose_arc_area(u_l, p.rho) - right_side_area(p, v_r);
  return std::max(2.0 * below / p.S, 0.0) * scale;
}

// R13
double material_ratio(const PitchProfile& p, double c) {
  if (c >= p.Rz) {
    return 1.0;
  }
  const double h = p.Rz - c;  // the level Rz - c
  const double left = h >= p.y_left_end ? 0.0 : p.u_c - left_side_abscissa(p, h);
  const double right = (p.S - p.u_c) - right_side_abscissa(p, h);
  return std::clamp((left + right) / p.S, 0.0, 1.0);
}

}  // namespace cutcalc::domain::roughness::detail
