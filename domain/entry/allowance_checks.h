#pragma once
// Main-time checks on several fields together (section 8, rules marked inferred in section 7.2).
// Private to domain/entry.

#include <optional>

#include "domain/common/result.h"
#include "domain/entry/main_time.h"

namespace cutcalc::domain::entry::detail {

// t <= D, whatever N1 (section 8).
std::optional<DomainError> check_width_of_cut(const MainTimeParams& params);

// H1 <= B within the width tolerance (section 7.2).
std::optional<DomainError> check_allowance_width(const MainTimeParams& params,
                                                 double part_width_mm);

// E27: with N1 > 1 there is no offset and H1 = B.
std::optional<DomainError> check_several_passes(const MainTimeParams& params, double part_width_mm);

}  // namespace cutcalc::domain::entry::detail
