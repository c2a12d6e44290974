#pragma once
// The cusp height Delta as a function of the feed per revolution for plotting (spec roughness.md
// B13): samples of B.4 over a range of feeds that shows the requested feed and, with a target, the
// largest feed B12, within the feeds the model accepts (B10). Units: mm, um.

#include <optional>
#include <vector>

#include "domain/common/result.h"
#include "domain/roughness/bore_milling.h"

namespace cutcalc::domain::roughness {

struct BoreMillingCurveParams {
  BoreMillingParams bore;                     // the request whose Delta(S) is drawn
  std::optional<double> max_feed_per_rev_mm;  // S(T) of B12, with a target only
  int points = 2;                             // number of samples, >= 1 (the API takes 2..1000)
};

struct BoreMillingCurvePoint {
  double feed_per_rev_mm = 0.0;  // S_j
  double cusp_height_um = 0.0;   // Delta(S_j) (B5)
};

struct BoreMillingCurve {
  double feed_max_mm = 0.0;                   // S_max (B13)
  std::vector<BoreMillingCurvePoint> points;  // S_j = S_max j / points, j = 1..points
};

// B13: samples S_j = S_max j / k, j = 1..k, each evaluated by compute_bore_milling_cusp, where
// S_max = min(S_lim, 1.5 S), or min(S_lim, max(1.5 S, 1.25 S(T))) with a target T. Errors: those of
// compute_bore_milling_cusp for the request itself.
Result<BoreMillingCurve> compute_bore_milling_curve(const BoreMillingCurveParams& params);

}  // namespace cutcalc::domain::roughness
