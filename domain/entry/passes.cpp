// E24-E25 and E37 of spec entry-and-main-time.md.

#include "domain/entry/passes.h"

#include <cmath>

#include "domain/common/numeric.h"

namespace cutcalc::domain::entry::detail {

// E24
Result<std::size_t> pass_count(double allowance_mm, double cut_mm, ErrorCode too_many) {
  const double count = ceil_count(allowance_mm / cut_mm);  // N
  // Written so that an infinite quotient also fails before the integer conversion.
  if (!(count <= static_cast<double>(kMaxPassCount))) {
    return make_limit_error(too_many, static_cast<double>(kMaxPassCount));
  }
  return static_cast<std::size_t>(count);
}

// E25 (not the paper's H - t floor(H/t), which is 0 when H/t is an integer) and E37
std::vector<double> pass_sizes(std::size_t count, double allowance_mm, double cut_mm,
                               PassSplit split) {
  const double N = static_cast<double>(count);  // N
  if (split == PassSplit::equal) {
    return std::vector<double>(count, allowance_mm / N);  // H/N each (E37)
  }
  std::vector<double> sizes(count, cut_mm);
  sizes.back() = allowance_mm - (N - 1.0) * cut_mm;
  return sizes;
}

// E37-E38
double lateral_cut_mm(std::size_t count, const Allowance& allowance, PassSplit split) {
  if (split == PassSplit::equal) {
    return allowance.width_mm / static_cast<double>(count);  // t_e = H1/N1
  }
  return allowance.width_of_cut_mm;  // t
}

}  // namespace cutcalc::domain::entry::detail
