#pragma once
// Spindle speed and feeds (E30-E33, E40). Private to domain/entry.

#include "domain/common/result.h"
#include "domain/entry/main_time.h"

namespace cutcalc::domain::entry::detail {

struct Feeds {
  double spindle_speed_rpm = 0.0;      // n
  double feed_per_rev_mm = 0.0;        // S_o
  double feed_mm_per_min = 0.0;        // S_m2
  double entry_feed_mm_per_min = 0.0;  // S_m1
};

// E30-E33. Error: entry_feed_exceeds_feed (S_z1 > S_z).
Result<Feeds> compute_feeds(const MainTimeParams& params);

// E40: the finishing level's n_f, S_m2f, S_m1f (params.finish given; `roughing` = E30-E33).
// Error: entry_feed_exceeds_feed (S_z1 > S_zf).
Result<Feeds> compute_finish_feeds(const MainTimeParams& params, const Feeds& roughing);

}  // namespace cutcalc::domain::entry::detail
