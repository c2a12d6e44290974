#pragma once
// The block-rate feed limit (spec polygon-holes.md P27, paper 000 eq. 6) and the program
// warnings of sections 7 and 8. Private to domain/polygon.

#include <vector>

#include "domain/polygon/biarc_fit.h"
#include "domain/polygon/polygon_hole.h"

namespace cutcalc::domain::polygon::detail {

// P27: L_min, the shortest block of one loop (unrounded arc length, units of the blocks).
double shortest_block_length(const std::vector<LoopBlock>& blocks);

// P27: 60000 L_min / block_time_ms (mm/min).
double max_feed_by_block_rate(double shortest_block_mm, double block_time_ms);

// phase_not_locked (always with feed_per_rev, section 7) and feed_exceeds_block_rate
// (F_prog = spindle_speed_rpm * feed_per_rev_mm above the P27 limit, section 8).
std::vector<program::Warning> program_warnings(Synchronization synchronization,
                                               double programmed_feed_mm_per_min,
                                               double max_feed_mm_per_min);

}  // namespace cutcalc::domain::polygon::detail
