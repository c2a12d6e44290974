// R2-R5 and R8 of spec roughness.md (paper 003). Each branch is written in a form free of
// cancellation, so that Rz keeps its relative accuracy down to a vanishing crest and next to the
// branch limits, and in a scale-free order of operations, so that no intermediate overflows.

#include "domain/roughness/crest_branches.h"

#include <algorithm>
#include <cmath>

namespace cutcalc::domain::roughness::detail {

namespace {

// sqrt(a) sqrt(b) rather than sqrt(a b): the product could overflow for huge lengths.
double sqrt_product(double a, double b) {
  return std::sqrt(std::max(a, 0.0)) * std::sqrt(std::max(b, 0.0));
}

}  // namespace

MinorEdgeAngle minor_edge_angle(double phi1_rad) {
  const double sin_half = std::sin(0.5 * phi1_rad);  // sin(phi1/2)
  MinorEdgeAngle phi1;
  phi1.sin_phi1 = std::sin(phi1_rad);
  phi1.cos_phi1 = std::cos(phi1_rad);
  phi1.tan_phi1 = std::tan(phi1_rad);
  // rho (1 - cos phi1) as 2 rho sin^2(phi1/2), as R4 prescribes: 1 - cos loses every digit for a
  // small phi1.
  phi1.two_sin_sq_half = 2.0 * sin_half * sin_half;
  return phi1;
}

// R2
BranchLimits branch_limits(double rho, const MinorEdgeAngle& phi1) {
  BranchLimits limits;
  limits.S_AB = 2.0 * rho * phi1.sin_phi1;
  limits.S_BC = rho + rho / phi1.sin_phi1;
  return limits;
}

// R3: Rz = (S^2/4) / (rho + sqrt(rho^2 - S^2/4)), the cancellation-free form of
// rho - sqrt(rho^2 - S^2/4); h (h / ...) keeps S^2 from overflowing.
double crest_height_nose_arc(double S, double rho) {
  const double h = 0.5 * S;  // S/2, half the pitch: the crest lies midway
  return h * (h / (rho + sqrt_product(rho - h, rho + h)));
}

// R4 (paper eq. 6): Rz = rho (1 - cos phi1) + sin phi1 (S cos phi1 - sqrt(S sin phi1 (2 rho -
// S sin phi1))). The bracket vanishes at S_AB, where its two terms are equal; multiplied by its
// conjugate it is S (S - S_AB) / (S cos phi1 + sqrt(...)), since S^2 cos^2 phi1 - S sin phi1
// (2 rho - S sin phi1) = S^2 - 2 rho S sin phi1.
double crest_height_nose_arc_and_minor_edge(double S, double rho, const MinorEdgeAngle& phi1,
                                            const BranchLimits& limits) {
  const double S_sin = S * phi1.sin_phi1;  // S sin(phi1) <= rho (1 + sin phi1) < 2 rho here
  const double root = sqrt_product(S_sin, 2.0 * rho - S_sin);
  const double bracket = S * ((S - limits.S_AB) / (S * phi1.cos_phi1 + root));
  return rho * phi1.two_sin_sq_half + phi1.sin_phi1 * bracket;
}

// R5: Rz = (S - rho) tan phi1 - rho (1/cos phi1 - 1), rearranged with S_BC = rho + rho/sin phi1
// into rho + (S - S_BC) tan phi1: the printed form subtracts two terms of size rho/cos phi1, which
// grow without bound as phi1 approaches 90 deg while Rz stays near rho.
double crest_height_minor_edge_and_main_edge(double S, double rho, const MinorEdgeAngle& phi1,
                                             const BranchLimits& limits) {
  return rho + (S - limits.S_BC) * phi1.tan_phi1;
}

// R8: each branch of R3-R5 solved for S. In the middle branch
// rho - (rho - T) cos phi1 = rho (1 - cos phi1) + T cos phi1 avoids the cancellation for small
// phi1.
double max_feed_for_crest_height(double T, double rho, const MinorEdgeAngle& phi1,
                                 const BranchLimits& limits) {
  const double T_AB = rho * phi1.two_sin_sq_half;  // Rz(S_AB) = rho (1 - cos phi1) (R6)
  if (T <= T_AB) {
    return 2.0 * sqrt_product(T, 2.0 * rho - T);
  }
  if (T <= rho) {  // Rz(S_BC) = rho (R6)
    return sqrt_product(T, 2.0 * rho - T) +
           (rho * phi1.two_sin_sq_half + T * phi1.cos_phi1) / phi1.sin_phi1;
  }
  return limits.S_BC + (T - rho) / phi1.tan_phi1;
}

}  // namespace cutcalc::domain::roughness::detail
