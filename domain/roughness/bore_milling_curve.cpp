// Delta(S) samples for plotting (spec roughness.md B13): every sample is one answer of B.4 through
// compute_bore_milling_cusp, the feed range bounded by S_lim (B10).

#include "domain/roughness/bore_milling_curve.h"

#include <algorithm>
#include <cstddef>

#include "domain/roughness/bore_milling_feed.h"
#include "domain/roughness/curve_feed_range.h"

namespace cutcalc::domain::roughness {

// B13
Result<BoreMillingCurve> compute_bore_milling_curve(const BoreMillingCurveParams& params) {
  // B.4 at the request's own feed: its errors are the curve's.
  const auto at_feed = compute_bore_milling_cusp(params.bore);
  if (!at_feed.ok()) {
    return at_feed.error();
  }
  BoreMillingCurve curve;
  // Never beyond what the model accepts (S_lim, B10).
  curve.feed_max_mm =
      std::min(detail::curve_feed_max_mm(params.bore.feed_per_rev_mm, params.max_feed_per_rev_mm),
               bore_milling_feed_limit_mm(params.bore));

  const int k = std::max(params.points, 1);
  curve.points.reserve(static_cast<std::size_t>(k));
  for (int j = 1; j <= k; ++j) {
    BoreMillingParams sample = params.bore;
    // S_j = S_max (j / k): the last sample is S_max itself.
    sample.feed_per_rev_mm = curve.feed_max_mm * (static_cast<double>(j) / k);
    const auto cusp = compute_bore_milling_cusp(sample);
    if (!cusp.ok()) {
      return cusp.error();
    }
    curve.points.push_back({sample.feed_per_rev_mm, cusp.value().cusp_height_um});
  }
  return curve;
}

}  // namespace cutcalc::domain::roughness
