#pragma once
// One pass of an end mill into and out of a workpiece: entry length, start and end positions and
// working stroke (spec entry-and-main-time.md E1-E23; paper 002, the Vitebsk calculator).
// Units: millimetres throughout. Inputs are range-checked by the caller (each field finite and in
// its own range); this function checks only what depends on several inputs together.

#include <optional>

#include "domain/common/result.h"
#include "domain/entry/contour.h"

namespace cutcalc::domain::entry {

struct ExitSide {
  Contour contour;             // must have the entry's width
  double length_mm = 0.0;      // L: entry origin to exit origin, > 0
  double extra_path_mm = 0.0;  // L1
  double overrun_mm = 2.0;     // L_per; ignored (0) for a wall exit
};

struct EntryLengthParams {
  double cutter_diameter_mm = 0.0;  // D
  double offset_mm = 0.0;           // K, signed, + towards +Y
  double approach_mm = 2.0;         // L_pod
  Contour entry;
  std::optional<ExitSide> exit;
};

struct Position {
  double x_mm = 0.0;  // X: against the feed from the frame's origin
  double y_mm = 0.0;  // Y: from the side edge (straight, wall) or the arc axis (arcs)
};

struct ExitResult {
  Position end;                    // X_k, Y_k (E8)
  double working_stroke_mm = 0.0;  // L_rx (E9)
};

struct EntryLengthResult {
  double engagement_length_mm = 0.0;  // L_vr1 (E6)
  double entry_length_mm = 0.0;       // L_vr = L_pod + L_vr1 (E6)
  Position start;                     // X_n, Y_n (E7)
  double steady_width_mm = 0.0;       // W (E2)
  std::optional<ExitResult> exit;
};

// E6-E9 with the unified formula E10-E12.
// Errors: no_contact, entry/exit_arc_wider_than_diameter, exit_width_mismatch,
// stroke_shorter_than_entry.
Result<EntryLengthResult> compute_entry_length(const EntryLengthParams& params);

}  // namespace cutcalc::domain::entry
