// E30-E33 and E40 of spec entry-and-main-time.md.

#include "domain/entry/feeds.h"

#include "domain/common/cutting_speed.h"

namespace cutcalc::domain::entry::detail {

namespace {

// E30 with the request's spindle speed or cutting speed (section 12).
double spindle_speed_rpm(const std::variant<SpindleSpeed, CuttingSpeed>& speed,
                         double cutter_diameter_mm) {
  if (const auto* rpm = std::get_if<SpindleSpeed>(&speed)) {
    return rpm->rpm;
  }
  return spindle_speed_rpm_at(std::get<CuttingSpeed>(speed).m_per_min, cutter_diameter_mm);
}

// E31-E33 at spindle speed n and feed per tooth S_z; the entry feed rule is the request's one
// for every level (E40 uses it with n_f and S_zf).
Result<Feeds> feeds_at(double n, double S_z, const MainTimeParams& params) {
  const double z = static_cast<double>(params.teeth);  // z
  Feeds feeds;
  feeds.spindle_speed_rpm = n;                                              // n (E30)
  feeds.feed_per_rev_mm = S_z * z;                                          // S_o (E31)
  feeds.feed_mm_per_min = feeds.spindle_speed_rpm * feeds.feed_per_rev_mm;  // S_m2 (E32)
  if (const auto* factor = std::get_if<EntryFeedFactor>(&params.entry_feed)) {
    feeds.entry_feed_mm_per_min = factor->factor * feeds.feed_mm_per_min;  // S_m1 (E33)
    return feeds;
  }
  const double S_z1 = std::get<EntryFeedPerTooth>(params.entry_feed).mm;  // S_z1
  // A faster entry than the steady cut would defeat the reduced entry feed (inferred in the spec).
  if (S_z1 > S_z) {
    return make_error(ErrorCode::entry_feed_exceeds_feed);
  }
  feeds.entry_feed_mm_per_min = feeds.spindle_speed_rpm * z * S_z1;  // S_m1 (E33)
  return feeds;
}

}  // namespace

// E30-E33
Result<Feeds> compute_feeds(const MainTimeParams& params) {
  return feeds_at(spindle_speed_rpm(params.speed, params.cutter_diameter_mm),
                  params.feed_per_tooth_mm, params);
}

// E40: n_f = finish speed (rpm or from v_f by E30), else n; S_m2f = n_f z S_zf; S_m1f by E33.
Result<Feeds> compute_finish_feeds(const MainTimeParams& params, const Feeds& roughing) {
  const Finish& finish = params.finish.value();
  const double n_f = finish.speed ? spindle_speed_rpm(*finish.speed, params.cutter_diameter_mm)
                                  : roughing.spindle_speed_rpm;  // n_f
  return feeds_at(n_f, finish.feed_per_tooth_mm, params);
}

}  // namespace cutcalc::domain::entry::detail
