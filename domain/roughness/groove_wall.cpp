// R1-R8 and R12 of spec roughness.md (paper 003): branch choice, Ra, the phi1 = 0 case and the
// target.

#include "domain/roughness/groove_wall.h"

#include <cmath>

#include "domain/common/numeric.h"
#include "domain/roughness/crest_branches.h"
#include "domain/roughness/pitch_profile.h"
#include "domain/roughness/units.h"

namespace cutcalc::domain::roughness {

using detail::kUmPerMm;

// R1-R12
Result<GrooveWallResult> compute_groove_wall_roughness(const GrooveWallParams& params) {
  const double S = params.feed_mm;                                  // S
  const double rho = params.nose_radius_mm;                         // rho
  const double phi1_rad = deg_to_rad(params.minor_edge_angle_deg);  // phi1
  // A phi1 too small to survive the conversion is phi1 = 0 for the model as well.
  if (phi1_rad == 0.0) {
    // R4 with phi1 = 0: the minor edge is the wall itself, so Rz = 0 for every feed and no target
    // can bound the feed (R.4).
    if (params.target_rz_um) {
      return make_error(ErrorCode::target_needs_minor_edge_angle);
    }
    // The profile is flat as well: Ra = 0 (R12).
    return GrooveWallResult{0.0, 0.0, CrestBranch::nose_arc_and_minor_edge, std::nullopt};
  }

  const detail::MinorEdgeAngle phi1 = detail::minor_edge_angle(phi1_rad);
  const detail::PitchProfile profile = detail::pitch_profile(S, rho, phi1);
  GrooveWallResult result;
  result.rz_um = profile.Rz * kUmPerMm;
  result.ra_um = detail::arithmetic_mean_deviation(profile) * kUmPerMm;
  result.branch = profile.branch;
  // Only for absurd magnitudes (a pitch near 1e290 mm at phi1 near 90 deg); no model answer is
  // better than an infinite one.
  if (!std::isfinite(result.rz_um) || !std::isfinite(result.ra_um)) {
    return make_error(ErrorCode::not_converged, "the crest height exceeds the range of a double");
  }
  if (params.target_rz_um) {
    const double T = *params.target_rz_um / kUmPerMm;  // T (R8)
    const double S_max =
        detail::max_feed_for_crest_height(T, rho, phi1, detail::branch_limits(rho, phi1));
    // A phi1 of a few 1e-300 deg is 0 for all practical purposes: S_max overflows like 1/phi1.
    if (!std::isfinite(S_max)) {
      return make_error(ErrorCode::target_needs_minor_edge_angle,
                        "the minor edge angle is too small for this target crest height: the "
                        "maximum feed exceeds every representable length");
    }
    result.max_feed_mm = S_max;
  }
  return result;
}

}  // namespace cutcalc::domain::roughness
