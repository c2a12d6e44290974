#pragma once
// The plan-view scheme of one pass, for drawing: the entry (and exit) contour, the workpiece near
// it, the strip, the steady band and the cutter axis positions, each side in its own workpiece
// frame (spec entry-and-main-time.md sections 3-5: X against the feed from the frame's origin, Y as
// for Y_n / Y_k). Units: millimetres.

#include <optional>
#include <vector>

#include "domain/common/result.h"
#include "domain/entry/entry_length.h"

namespace cutcalc::domain::entry {

// Segments an arc contour is sampled with (uniform in the arc's angle; ends and apex exact).
inline constexpr int kSchemeArcSegments = 128;

// A lateral interval in frame Y.
struct LateralRange {
  double y_min_mm = 0.0;
  double y_max_mm = 0.0;
};

enum class SchemePositionKind {
  start,          // X_n, Y_n (E7)
  first_contact,  // X_n - L_pod: the disc touches the contour (E5, xc0)
  saturation,     // X_n - L_vr: the engaged width reaches W (E5, xcs)
  end,            // X_k, Y_k (E8)
};

struct SchemePosition {
  SchemePositionKind kind = SchemePositionKind::start;
  Position axis;  // the cutter axis, frame coordinates
};

// One contour in its own frame.
struct SchemeSide {
  // The contour from Y(-h) to Y(+h): e(y) for the entry, f(y) for the exit, the face for a wall.
  // 2 points for a straight edge or wall, kSchemeArcSegments + 1 for an arc.
  std::vector<Position> contour;
  // The contour followed by the two far corners of the strip (downstream of an entry, upstream of
  // an exit): a simple polygon, not closed (the last point is not the first).
  std::vector<Position> workpiece_outline;
  LateralRange strip;  // Y(-h) .. Y(+h)
  LateralRange band;   // the steady band S = [a, b] (E2) in frame Y
  std::vector<SchemePosition> positions;
};

struct EntryScheme {
  double cutter_radius_mm = 0.0;   // r (E1)
  SchemeSide entry;                // positions: start, first_contact, saturation
  std::optional<SchemeSide> exit;  // when params.exit; positions: end
};

// Sections 3-5, E2, E5-E8. `result` must be compute_entry_length(params).
// The workpiece outline reaches max(3 D, L_vr + D) beyond the contour's farthest point.
// Errors: no_contact (a band the result says exists is empty), not_converged (a coordinate too
// large to represent).
Result<EntryScheme> entry_scheme(const EntryLengthParams& params, const EntryLengthResult& result);

}  // namespace cutcalc::domain::entry
