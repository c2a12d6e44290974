#pragma once
// The crest height Rz_p as a function of the pitch S for plotting (spec roughness.md part R):
// samples of R1-R5 over a range of feeds that shows the requested feed and, with a target, the
// largest feed R8. Units: mm, um, degrees.

#include <vector>

#include "domain/common/result.h"
#include "domain/roughness/groove_wall.h"

namespace cutcalc::domain::roughness {

struct GrooveWallCurveParams {
  GrooveWallParams groove;  // the request whose Rz(S) is drawn (its feed and optional target)
  int points = 2;           // number of samples, >= 1 (the API takes 2..1000)
};

struct GrooveWallCurvePoint {
  double feed_mm = 0.0;  // S
  double rz_um = 0.0;    // Rz_p(S) (R1)
  CrestBranch branch = CrestBranch::nose_arc;
};

struct GrooveWallCurve {
  double feed_max_mm = 0.0;                  // S_max = max(1.5 S, 1.25 max_feed_mm)
  std::vector<GrooveWallCurvePoint> points;  // S_k = S_max k / points, k = 1..points
};

// Samples S_k = S_max k / n, k = 1..n, each evaluated by compute_groove_wall_roughness (R1-R8,
// without the target), where S_max = 1.5 S, or max(1.5 S, 1.25 S(T)) with a target T (R8).
// Errors: those of compute_groove_wall_roughness for the request itself
// (target_needs_minor_edge_angle), and target_needs_minor_edge_angle when 1.25 S(T) exceeds the
// range of a double (a vanishing phi1).
Result<GrooveWallCurve> compute_groove_wall_curve(const GrooveWallCurveParams& params);

}  // namespace cutcalc::domain::roughness
