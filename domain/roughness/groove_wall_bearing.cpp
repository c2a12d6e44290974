// R13-R14 of spec roughness.md R.7: the material ratio at evenly spaced depths below the crest.

#include "domain/roughness/groove_wall_bearing.h"

#include <algorithm>
#include <cstddef>
#include <optional>

#include "domain/common/numeric.h"
#include "domain/roughness/crest_branches.h"
#include "domain/roughness/pitch_profile.h"
#include "domain/roughness/units.h"

namespace cutcalc::domain::roughness {

// R13-R14
Result<std::vector<BearingPoint>> compute_groove_wall_bearing_curve(const GrooveWallParams& params,
                                                                    int points) {
  GrooveWallParams without_target = params;
  without_target.target_rz_um = std::nullopt;
  const auto at_feed = compute_groove_wall_roughness(without_target);
  if (!at_feed.ok()) {
    return at_feed.error();
  }
  const int n = std::max(points, 1);
  std::vector<BearingPoint> curve;
  curve.reserve(static_cast<std::size_t>(n));
  const double phi1_rad = deg_to_rad(params.minor_edge_angle_deg);  // phi1
  if (phi1_rad == 0.0) {
    // A flat wall: all of it is material at every depth (R13).
    curve.assign(static_cast<std::size_t>(n), BearingPoint{0.0, 1.0});
    return curve;
  }
  const detail::PitchProfile profile = detail::pitch_profile(params.feed_mm, params.nose_radius_mm,
                                                             detail::minor_edge_angle(phi1_rad));
  for (int k = 1; k <= n; ++k) {
    // c_k = Rz k / n; the last depth is Rz itself, where the ratio is 1.
    const double c = k == n ? profile.Rz : profile.Rz * (static_cast<double>(k) / n);
    curve.push_back({c * detail::kUmPerMm, detail::material_ratio(profile, c)});
  }
  return curve;
}

}  // namespace cutcalc::domain::roughness
