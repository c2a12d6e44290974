#pragma once
// The feed range S_max of a height-against-feed curve (the groove-wall Rz(S) plot, bore-milling
// B13). Private to domain/roughness.

#include <algorithm>
#include <optional>

namespace cutcalc::domain::roughness::detail {

// The range shows the requested feed S with room to its right and, with a target, the largest
// feed S(T) a quarter beyond it: max(1.5 S, 1.25 S(T)) (B13; the groove-wall curve likewise).
inline double curve_feed_max_mm(double feed_mm, std::optional<double> max_feed_mm) {
  constexpr double kFeedMargin = 1.5;          // S_max >= 1.5 S
  constexpr double kMaxFeedMargin = 1.25;      // S_max >= 1.25 S(T)
  double feed_max_mm = kFeedMargin * feed_mm;  // S_max
  if (max_feed_mm) {
    feed_max_mm = std::max(feed_max_mm, kMaxFeedMargin * *max_feed_mm);
  }
  return feed_max_mm;
}

}  // namespace cutcalc::domain::roughness::detail
