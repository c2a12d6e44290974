#pragma once
// Unit conversions of spec roughness.md ("Common rules"), private to domain/roughness. The spec
// fixes the double constants so that every implementation rounds the same way (x * (pi/180), not
// (x * pi) / 180 as domain/common/numeric.h does).

namespace cutcalc::domain::roughness::detail {

inline constexpr double kRadPerDeg = 0.017453292519943295;  // pi/180
inline constexpr double kUmPerMm = 1000.0;

}  // namespace cutcalc::domain::roughness::detail
