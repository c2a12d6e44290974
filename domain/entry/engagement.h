#pragma once
// The unified engagement formula E10-E12: first contact, saturation and end position of a disc
// cutter whose axis runs along y = K, for any contour. Private to domain/entry.

#include <optional>

#include "domain/entry/contour.h"

namespace cutcalc::domain::entry::detail {

// A lateral position with its offset from the axis and the disc's half chord there, both known
// exactly at the band ends (section 5: never recompute u from a rounded y).
struct BandPoint {
  double y_mm = 0.0;           // y
  double u_mm = 0.0;           // u = y - K
  double half_chord_mm = 0.0;  // s(u) (E1)
};

// The steady band S = [a, b] (E2).
struct Band {
  BandPoint lower;        // a
  BandPoint upper;        // b
  double width_mm = 0.0;  // W
};

// The workpiece seen by one contour: the axis and the lateral edges of the material it cuts, all
// in that contour's internal frame. Usually the edges are -h and h; a later lateral pass of an arc
// starts at its strip's edge instead (section 7.2).
struct LateralSetting {
  double axis_y_mm = 0.0;         // K
  double cutter_radius_mm = 0.0;  // r
  double lower_edge_mm = 0.0;     // -h, or the strip's edge
  double upper_edge_mm = 0.0;     // h
};

// E2: the band, or nothing when W <= 0 (tangency included), compared exactly as section 8 says.
std::optional<Band> steady_band(const LateralSetting& setting);

// E10: xc0 = min psi and xcs = max psi over the band.
struct EntryExtremes {
  double first_contact_mm = 0.0;  // xc0
  double saturation_mm = 0.0;     // xcs
};
EntryExtremes entry_extremes(const Contour& contour, const LateralSetting& setting,
                             const Band& band);

// E11: x_end = max phi over the band. Not for a wall exit (E22).
double exit_end_x_mm(const Contour& contour, const LateralSetting& setting, const Band& band);

}  // namespace cutcalc::domain::entry::detail
