#pragma once
// Numbers and sizes of the lateral and depth passes (E24, E25, E37, E39). Private to domain/entry.

#include <cstddef>
#include <vector>

#include "domain/common/result.h"
#include "domain/entry/main_time.h"

namespace cutcalc::domain::entry::detail {

// E24: N = ceil(allowance / cut - 1e-9), at least 1. Error `too_many` (limit kMaxPassCount) above
// kMaxPassCount.
Result<std::size_t> pass_count(double allowance_mm, double cut_mm, ErrorCode too_many);

// E25: N - 1 full cuts, then the remainder allowance - (N - 1) cut; E37 (equal): N times
// allowance / N.
std::vector<double> pass_sizes(std::size_t count, double allowance_mm, double cut_mm,
                               PassSplit split);

// E37-E38: the width every lateral pass but the last is laid with: t (last_smaller) or H1/N1
// (equal).
double lateral_cut_mm(std::size_t count, const Allowance& allowance, PassSplit split);

}  // namespace cutcalc::domain::entry::detail
