#pragma once
// Unit conversions of spec roughness.md ("Common rules"), private to domain/roughness. Degrees and
// radians: domain/common/numeric.h.

namespace cutcalc::domain::roughness::detail {

inline constexpr double kUmPerMm = 1000.0;

}  // namespace cutcalc::domain::roughness::detail
