#pragma once
// Which numeric response fields are quantities that can never be negative, by their JSON key:
// shared by the tests' answer checks (support/sanity_checks.cpp) and the fuzzers' oracle
// (fuzz/fuzz_support.cpp), so that both hold the API to the same promise.

#include <string_view>

namespace cutcalc::test_support {

// Lengths (_mm, _mm2, _um) and times (_min, not rates _per_min) are >= 0; coordinates, offsets and
// the lateral limits of an entry-length scheme (frame Y, negative for arcs), the X steps of a
// lathe flat's step table (dX < 0 in the second half, lathe-flat.md F8) and the time lost to a
// machine's dynamics (T_e - T_n, negative where blending shortens the path, machine-time.md
// section 6) are signed.
inline bool is_non_negative_quantity(std::string_view key) {
  if (key == "x_mm" || key == "y_mm" || key == "offset_mm" || key == "axis_y_mm" ||
      key == "y_min_mm" || key == "y_max_mm" || key == "dx_mm" || key == "dynamics_time_min") {
    return false;
  }
  if (key.ends_with("_mm") || key.ends_with("_mm2") || key.ends_with("_um")) {
    return true;
  }
  return key.ends_with("_min") && !key.ends_with("_per_min");
}

}  // namespace cutcalc::test_support
