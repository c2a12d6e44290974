// Contour pair checks of section 8 (spec entry-and-main-time.md).

#include "domain/entry/contour_checks.h"

#include <algorithm>
#include <cmath>

namespace cutcalc::domain::entry::detail {

namespace {

constexpr double kWidthRelativeTolerance = 1e-9;  // section 8

bool arc_wider_than_diameter(const Contour& contour) {
  const bool arc =
      contour.kind == ContourKind::convex_arc || contour.kind == ContourKind::concave_arc;
  return arc && contour.width_mm && *contour.width_mm > 2.0 * contour.radius_mm;
}

}  // namespace

bool same_width(double first_mm, double second_mm) {
  const double scale = std::max(std::abs(first_mm), std::abs(second_mm));
  return std::abs(first_mm - second_mm) <= kWidthRelativeTolerance * scale;
}

// E3 (B <= 2R)
std::optional<DomainError> check_arc_widths(const Contour& entry, const Contour* exit) {
  if (arc_wider_than_diameter(entry)) {
    return make_error(ErrorCode::entry_arc_wider_than_diameter);
  }
  if (exit != nullptr && arc_wider_than_diameter(*exit)) {
    return make_error(ErrorCode::exit_arc_wider_than_diameter);
  }
  return std::nullopt;
}

std::optional<DomainError> check_exit_width(const Contour& exit, double part_width) {
  if (!same_width(part_width_mm(exit), part_width)) {
    return make_error(ErrorCode::exit_width_mismatch);
  }
  return std::nullopt;
}

}  // namespace cutcalc::domain::entry::detail
