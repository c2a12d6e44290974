#pragma once
// Checks on a pair of contours that the API cannot make field by field (section 8).
// Private to domain/entry.

#include <optional>

#include "domain/common/result.h"
#include "domain/entry/contour.h"

namespace cutcalc::domain::entry::detail {

// Section 8: widths agree within a relative tolerance of 1e-9.
bool same_width(double first_mm, double second_mm);

// An arc cannot span more than its diameter (width_mm > 2 radius_mm). Checks entry then exit.
std::optional<DomainError> check_arc_widths(const Contour& entry, const Contour* exit);

// The exit contour must span the entry's (or the part's) width B.
std::optional<DomainError> check_exit_width(const Contour& exit, double part_width_mm);

}  // namespace cutcalc::domain::entry::detail
