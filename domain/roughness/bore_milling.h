#pragma once
// Cusp height between adjacent tooth paths when an end mill machines a bore by circular
// interpolation (spec roughness.md part B, B1-B8; paper 001). Units: mm inside, cusp heights in
// micrometres, degrees. Inputs are range-checked by the caller; this function checks what
// depends on several inputs together.

#include "domain/common/milling_sense.h"
#include "domain/common/result.h"

namespace cutcalc::domain::roughness {

struct BoreMillingParams {
  double bore_radius_mm = 0.0;    // R > 0
  double cutter_radius_mm = 0.0;  // r, 0 < r < R
  int teeth = 1;                  // n >= 1
  double feed_per_rev_mm = 0.0;   // S_n: advance of the cutter centre per spindle revolution
  MillingSense milling = MillingSense::up;  // up: spindle and orbit turn the same way
};

struct BoreMillingResult {
  double cusp_height_um = 0.0;              // Delta, exact (B5)
  double approximate_cusp_height_um = 0.0;  // f_zb^2/8 (1/r - 1/R) (B8)
  double feed_per_tooth_mm = 0.0;           // f_z on the centre path (B2)
  double feed_per_tooth_on_bore_mm = 0.0;   // f_zb (B2)
  double pitch_angle_deg = 0.0;             // alpha (B3)
};

// B1-B8 with the root finding of B.4. Errors: cutter_not_smaller_than_bore, bore_feed_too_large,
// not_converged (a bug: the bracketed root search did not finish).
Result<BoreMillingResult> compute_bore_milling_cusp(const BoreMillingParams& params);

// B.4 steps 1-4 alone: whether the model accepts this bore, cutter, teeth, sense and feed (the
// predicate of B10).
bool bore_milling_feed_accepted(const BoreMillingParams& params);

}  // namespace cutcalc::domain::roughness
