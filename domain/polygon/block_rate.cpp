// P27 of spec polygon-holes.md and the warnings of sections 7 and 8.

#include "domain/polygon/block_rate.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <limits>
#include <string>
#include <utility>

namespace cutcalc::domain::polygon::detail {

namespace {

// 8 significant digits: free text for people, short whatever the magnitude.
std::string compact(double value) {
  std::array<char, 64> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                    std::chars_format::general, 8);
  return std::string(buffer.data(), result.ptr);
}

}  // namespace

// P27
double shortest_block_length(const std::vector<LoopBlock>& blocks) {
  double shortest = std::numeric_limits<double>::infinity();
  for (const LoopBlock& block : blocks) {
    shortest = std::min(shortest, block.arc.length);
  }
  return blocks.empty() ? 0.0 : shortest;
}

// P27
double max_feed_by_block_rate(double shortest_block_mm, double block_time_ms) {
  return 60000.0 * shortest_block_mm / block_time_ms;
}

std::vector<program::Warning> program_warnings(Synchronization synchronization,
                                               double programmed_feed_mm_per_min,
                                               double max_feed_mm_per_min) {
  // Short details without commas or parentheses: they also become program comment lines.
  std::vector<program::Warning> warnings;
  if (programmed_feed_mm_per_min > max_feed_mm_per_min) {
    std::string detail = "feed " + compact(programmed_feed_mm_per_min) +
                         " mm/min exceeds the block-rate limit " + compact(max_feed_mm_per_min) +
                         " mm/min: the control will starve";
    warnings.push_back({program::WarningCode::feed_exceeds_block_rate, std::move(detail)});
  }
  if (synchronization == Synchronization::feed_per_rev) {
    warnings.push_back(
        {program::WarningCode::phase_not_locked,
         "G95 does not lock the rotor angle to the path: start with corner 0 pointing -Y"});
  }
  return warnings;
}

}  // namespace cutcalc::domain::polygon::detail
