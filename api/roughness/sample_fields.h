#pragma once
// The request fields the roughness endpoints share: a height target's range and the opt-in sample
// counts of their plots (groove wall: target_rz_um, curve_points, bearing_points; bore milling:
// target_cusp_um, curve_points).

#include <cstdint>
#include <optional>
#include <string_view>

#include "api/field_reader.h"

namespace cutcalc::api::roughness {

// Height targets up to 1 km in micrometres: no meaningful surface is rougher.
inline constexpr double kMaxTargetUm = 1.0e9;

// A sample count: absent, nullopt; otherwise a whole number 2..1000 (a line needs two points;
// 1000 is finer than any plot), 0 after an error the reader has recorded.
inline std::optional<int> optional_sample_count(ObjectReader& in, std::string_view key) {
  constexpr std::int64_t kMinSamples = 2;
  constexpr std::int64_t kMaxSamples = 1000;
  if (!in.has(key)) {
    return std::nullopt;
  }
  return static_cast<int>(in.required_integer(key, kMinSamples, kMaxSamples).value_or(0));
}

}  // namespace cutcalc::api::roughness
