// Rz(S) samples for plotting (spec roughness.md part R): every sample is one evaluation of
// R1-R5 through compute_groove_wall_roughness, the feed range from R8's largest feed.

#include "domain/roughness/groove_wall_curve.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>

#include "domain/roughness/curve_feed_range.h"

namespace cutcalc::domain::roughness {

Result<GrooveWallCurve> compute_groove_wall_curve(const GrooveWallCurveParams& params) {
  // R1-R8 at the request's own feed: its errors are the curve's, and R8 gives S(T).
  const auto at_feed = compute_groove_wall_roughness(params.groove);
  if (!at_feed.ok()) {
    return at_feed.error();
  }
  GrooveWallCurve curve;
  curve.feed_max_mm = detail::curve_feed_max_mm(params.groove.feed_mm, at_feed.value().max_feed_mm);
  if (!std::isfinite(curve.feed_max_mm)) {
    return make_error(ErrorCode::target_needs_minor_edge_angle,
                      "the minor edge angle is too small for this target crest height: the feed "
                      "range of the curve exceeds every representable length");
  }

  const int n = std::max(params.points, 1);
  curve.points.reserve(static_cast<std::size_t>(n));
  for (int k = 1; k <= n; ++k) {
    GrooveWallParams sample = params.groove;
    // S_k = S_max (k / n): the last sample is S_max itself.
    sample.feed_mm = curve.feed_max_mm * (static_cast<double>(k) / n);
    sample.target_rz_um = std::nullopt;
    const auto rz = compute_groove_wall_roughness(sample);
    if (!rz.ok()) {
      return rz.error();
    }
    curve.points.push_back({sample.feed_mm, rz.value().rz_um, rz.value().branch});
  }
  return curve;
}

}  // namespace cutcalc::domain::roughness
