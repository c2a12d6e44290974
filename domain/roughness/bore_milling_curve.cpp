// Delta(S) samples for plotting (spec roughness.md B13): every sample is one answer of B.4 through
// compute_bore_milling_cusp, the feed range bounded by S_lim (B10).

#include "domain/roughness/bore_milling_curve.h"

#include <algorithm>
#include <cstddef>

#include "domain/roughness/bore_milling_feed.h"

namespace cutcalc::domain::roughness {

namespace {

// The range shows the requested feed with room to its right and, with a target, the largest feed
// S(T) a quarter beyond it, as the groove-wall curve does; never beyond what the model accepts.
constexpr double kFeedMargin = 1.5;      // S_max >= 1.5 S
constexpr double kMaxFeedMargin = 1.25;  // S_max >= 1.25 S(T)

}  // namespace

// B13
Result<BoreMillingCurve> compute_bore_milling_curve(const BoreMillingCurveParams& params) {
  // B.4 at the request's own feed: its errors are the curve's.
  const auto at_feed = compute_bore_milling_cusp(params.bore);
  if (!at_feed.ok()) {
    return at_feed.error();
  }
  BoreMillingCurve curve;
  curve.feed_max_mm = kFeedMargin * params.bore.feed_per_rev_mm;
  if (params.max_feed_per_rev_mm) {
    curve.feed_max_mm = std::max(curve.feed_max_mm, kMaxFeedMargin * *params.max_feed_per_rev_mm);
  }
  curve.feed_max_mm = std::min(curve.feed_max_mm, bore_milling_feed_limit_mm(params.bore));

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
