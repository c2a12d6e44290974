// E30-E33 of spec entry-and-main-time.md.

#include "domain/entry/feeds.h"

#include <numbers>

namespace cutcalc::domain::entry::detail {

namespace {

// E30: n = 1000 v / (pi D), not rounded to machine steps (section 12).
double spindle_speed_rpm(const MainTimeParams& params) {
  if (const auto* speed = std::get_if<SpindleSpeed>(&params.speed)) {
    return speed->rpm;
  }
  const double v = std::get<CuttingSpeed>(params.speed).m_per_min;  // v
  return 1000.0 * v / (std::numbers::pi * params.cutter_diameter_mm);
}

}  // namespace

// E30-E33
Result<Feeds> compute_feeds(const MainTimeParams& params) {
  const double z = static_cast<double>(params.teeth);  // z
  Feeds feeds;
  feeds.spindle_speed_rpm = spindle_speed_rpm(params);                      // n (E30)
  feeds.feed_per_rev_mm = params.feed_per_tooth_mm * z;                     // S_o (E31)
  feeds.feed_mm_per_min = feeds.spindle_speed_rpm * feeds.feed_per_rev_mm;  // S_m2 (E32)
  if (const auto* factor = std::get_if<EntryFeedFactor>(&params.entry_feed)) {
    feeds.entry_feed_mm_per_min = factor->factor * feeds.feed_mm_per_min;  // S_m1 (E33)
    return feeds;
  }
  const double S_z1 = std::get<EntryFeedPerTooth>(params.entry_feed).mm;  // S_z1
  // A faster entry than the steady cut would defeat the reduced entry feed (inferred in the spec).
  if (S_z1 > params.feed_per_tooth_mm) {
    return make_error(ErrorCode::entry_feed_exceeds_feed);
  }
  feeds.entry_feed_mm_per_min = feeds.spindle_speed_rpm * z * S_z1;  // S_m1 (E33)
  return feeds;
}

}  // namespace cutcalc::domain::entry::detail
