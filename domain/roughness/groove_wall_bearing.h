#pragma once
// The bearing (Abbott-Firestone) curve of the groove side wall profile over one pitch (spec
// roughness.md R.7, R13-R14; paper 003). Units: mm, um, degrees.

#include <vector>

#include "domain/common/result.h"
#include "domain/roughness/groove_wall.h"

namespace cutcalc::domain::roughness {

struct BearingPoint {
  double depth_um = 0.0;        // c_k, depth below the highest peak
  double material_ratio = 0.0;  // Rmr(c_k) in [0, 1] (R13)
};

// R14: n points c_k = Rz k / n, k = 1..n (the last is Rz, ratio 1), with Rmr(c_k) of R13; with
// phi1 = 0 (a flat wall) every depth is 0 and every ratio 1. The target of the request plays no
// part. Errors: those of compute_groove_wall_roughness without its target (not_converged).
Result<std::vector<BearingPoint>> compute_groove_wall_bearing_curve(const GrooveWallParams& params,
                                                                    int points);

}  // namespace cutcalc::domain::roughness
