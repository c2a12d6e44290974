#pragma once
// The feeds of spec roughness.md addition B.9: the largest feed the bore-milling model accepts
// (B9-B10) and the largest feed whose cusp stays within a target (B12). Units: mm, um.

#include "domain/common/result.h"
#include "domain/roughness/bore_milling.h"

namespace cutcalc::domain::roughness {

// B9-B10: S_lim, the largest feed per revolution in (0, S_top) that B.4 steps 2-4 accept for this
// bore, cutter, teeth and sense (feed_per_rev_mm is ignored). Needs r < R.
double bore_milling_feed_limit_mm(const BoreMillingParams& params);

// B12: the largest feed per revolution S in (0, S_lim] with Delta(S) <= target_cusp_um
// (feed_per_rev_mm is ignored). Needs r < R and a target > 0. Errors:
// target_cusp_unreachable (Delta(S_lim) < target; limit = Delta(S_lim) in um).
Result<double> bore_milling_max_feed_mm(const BoreMillingParams& params, double target_cusp_um);

}  // namespace cutcalc::domain::roughness
