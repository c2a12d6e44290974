// Part width of a contour (spec entry-and-main-time.md, E3 and section 7.2).

#include "domain/entry/contour.h"

namespace cutcalc::domain::entry {

// E3: a convex arc without width_mm spans its whole diameter. The other kinds always carry a
// width (the API requires it); a missing one reads as 0, which the band check then rejects as
// no contact instead of inventing a width.
double part_width_mm(const Contour& contour) {
  if (contour.kind == ContourKind::convex_arc) {
    return contour.width_mm.value_or(2.0 * contour.radius_mm);
  }
  return contour.width_mm.value_or(0.0);
}

}  // namespace cutcalc::domain::entry
