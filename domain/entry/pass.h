#pragma once
// One pass of the cutter into and out of its workpiece (E6-E9, E22, E23), shared by the
// entry-length endpoint and every lateral pass of main time. Private to domain/entry.

#include <optional>

#include "domain/common/result.h"
#include "domain/entry/contour.h"
#include "domain/entry/engagement.h"
#include "domain/entry/entry_length.h"

namespace cutcalc::domain::entry::detail {

// One contour as this pass sees it: the contour function and the lateral setting in its frame.
struct PassSide {
  Contour contour;
  LateralSetting lateral;
};

struct PassExit {
  PassSide side;
  double length_mm = 0.0;      // L: from this pass's entry origin to its exit origin
  double extra_path_mm = 0.0;  // L1
  double overrun_mm = 0.0;     // L_per as given; a wall exit replaces it with 0 (E22)
};

struct PassPlan {
  double approach_mm = 0.0;  // L_pod
  PassSide entry;
  std::optional<PassExit> exit;
};

struct PassGeometry {
  EntryLengthResult result;
  double steady_travel_mm = 0.0;  // L_rx - L_vr, computed directly (E23); 0 without an exit
};

// E6-E9 and E22-E23. Errors: no_contact, stroke_shorter_than_entry.
Result<PassGeometry> solve_pass(const PassPlan& plan);

}  // namespace cutcalc::domain::entry::detail
