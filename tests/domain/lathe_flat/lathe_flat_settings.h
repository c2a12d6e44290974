#pragma once
// The flat the lathe-flat domain tests start from.

#include "domain/lathe_flat/lathe_flat.h"

namespace cutcalc::domain::lathe_flat::settings {

// Section 9's flat: D32, t = 1 (R2 = 16, d = 15).
inline constexpr FlatSection kPaper{16.0, 15.0, 0.0};    // point tool
inline constexpr FlatSection kPaperR5{16.0, 15.0, 5.0};  // R5 end mill

// Section 9: D32, t = 1, point tool, N = 10, f = 100 mm/min.
inline LatheFlatParams paper_flat() {
  LatheFlatParams p;
  p.part_diameter_mm = 32.0;
  p.flat_depth_mm = 1.0;
  p.steps = 10;
  p.feed_mm_per_min = 100.0;
  return p;
}

}  // namespace cutcalc::domain::lathe_flat::settings
