// Allowance and placement checks of main time (spec entry-and-main-time.md sections 7.2 and 8).

#include "domain/entry/allowance_checks.h"

#include "domain/entry/contour_checks.h"

namespace cutcalc::domain::entry::detail {

std::optional<DomainError> check_width_of_cut(const MainTimeParams& params) {
  // E29 relies on it: a pass wider than the cutter would leave an uncut rib.
  if (params.allowance.width_of_cut_mm > params.cutter_diameter_mm) {
    return make_error(ErrorCode::width_of_cut_exceeds_diameter);
  }
  return std::nullopt;
}

std::optional<DomainError> check_allowance_width(const MainTimeParams& params,
                                                 double part_width_mm) {
  const double H1 = params.allowance.width_mm;  // H1
  if (H1 > part_width_mm && !same_width(H1, part_width_mm)) {
    return make_error(ErrorCode::allowance_wider_than_part);
  }
  return std::nullopt;
}

// E27: the passes are laid from the side edge Y_p = 0, so there is no free offset, and they can
// only end at the far edge if the allowance spans the whole part. An offset of 0 is the default
// (no offset), so it is accepted as if it were absent.
std::optional<DomainError> check_several_passes(const MainTimeParams& params,
                                                double part_width_mm) {
  if (params.offset_mm.value_or(0.0) != 0.0) {
    return make_error(ErrorCode::offset_with_several_passes);
  }
  if (!same_width(params.allowance.width_mm, part_width_mm)) {
    return make_error(ErrorCode::allowance_not_full_width);
  }
  return std::nullopt;
}

}  // namespace cutcalc::domain::entry::detail
