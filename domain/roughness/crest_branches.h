#pragma once
// The three crest branches of the groove side wall (spec roughness.md R2-R5) and the inverse R8,
// for phi1 > 0. Lengths in mm. Private to domain/roughness.

namespace cutcalc::domain::roughness::detail {

// phi1 with the trigonometric values every branch needs, computed once.
struct MinorEdgeAngle {
  double sin_phi1 = 0.0;         // sin(phi1)
  double cos_phi1 = 0.0;         // cos(phi1)
  double tan_phi1 = 0.0;         // tan(phi1)
  double two_sin_sq_half = 0.0;  // 2 sin^2(phi1/2) = 1 - cos(phi1) without cancellation
};

MinorEdgeAngle minor_edge_angle(double phi1_rad);

// R2: the feeds at which the crest moves from one pair of edges to the next.
struct BranchLimits {
  double S_AB = 0.0;  // S_AB = 2 rho sin(phi1): nose arc / minor edge
  double S_BC = 0.0;  // S_BC = rho (1 + 1/sin(phi1)): minor edge / main edge
};

BranchLimits branch_limits(double rho, const MinorEdgeAngle& phi1);

// R3: two nose arcs, 0 < S <= S_AB (and S < 2 rho).
double crest_height_nose_arc(double S, double rho);

// R4 (paper eq. 6): previous nose arc and current minor edge, S_AB <= S <= S_BC.
double crest_height_nose_arc_and_minor_edge(double S, double rho, const MinorEdgeAngle& phi1,
                                            const BranchLimits& limits);

// R5: current minor edge and previous main edge, S >= S_BC.
double crest_height_minor_edge_and_main_edge(double S, double rho, const MinorEdgeAngle& phi1,
                                             const BranchLimits& limits);

// R8: the largest S with Rz(S) <= T (T > 0, mm). May overflow to infinity for a vanishing phi1;
// the caller decides what that means.
double max_feed_for_crest_height(double T, double rho, const MinorEdgeAngle& phi1,
                                 const BranchLimits& limits);

}  // namespace cutcalc::domain::roughness::detail
