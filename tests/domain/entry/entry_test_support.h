#pragma once
// Builders for entry-length / main-time parameters used by the domain tests.

#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "domain/common/result.h"
#include "domain/entry/contour.h"
#include "domain/entry/entry_length.h"
#include "domain/entry/main_time.h"

namespace cutcalc::test {

namespace entry_api = cutcalc::domain::entry;

// Tolerances of the entry tests.
inline constexpr double kTol = 1e-9;    // mm, values from closed forms
inline constexpr double kSpec2 = 5e-3;  // numbers the spec prints with 2 decimals
inline constexpr double kMm = 1e-9;     // mm, rpm, mm/min from exact expressions (main time)
inline constexpr double kMin = 1e-12;   // min from exact expressions (main time)

inline entry_api::Contour straight_contour(double width, double angle_deg = 90.0) {
  entry_api::Contour c;
  c.kind = entry_api::ContourKind::straight;
  c.width_mm = width;
  c.angle_deg = angle_deg;
  return c;
}

inline entry_api::Contour convex_contour(double radius,
                                         std::optional<double> width = std::nullopt) {
  entry_api::Contour c;
  c.kind = entry_api::ContourKind::convex_arc;
  c.radius_mm = radius;
  c.width_mm = width;
  return c;
}

inline entry_api::Contour concave_contour(double radius, double width) {
  entry_api::Contour c;
  c.kind = entry_api::ContourKind::concave_arc;
  c.radius_mm = radius;
  c.width_mm = width;
  return c;
}

inline entry_api::Contour wall_contour(double width) {
  entry_api::Contour c;
  c.kind = entry_api::ContourKind::wall;
  c.width_mm = width;
  return c;
}

// One pass without an exit.
inline entry_api::EntryLengthParams entry_only(double diameter, double offset,
                                               const entry_api::Contour& entry,
                                               double approach = 2.0) {
  entry_api::EntryLengthParams p;
  p.cutter_diameter_mm = diameter;
  p.offset_mm = offset;
  p.approach_mm = approach;
  p.entry = entry;
  return p;
}

// One pass with an exit.
inline entry_api::EntryLengthParams entry_exit(double diameter, double offset,
                                               const entry_api::Contour& entry,
                                               const entry_api::Contour& exit, double length,
                                               double approach = 2.0, double extra_path = 0.0,
                                               double overrun = 2.0) {
  entry_api::EntryLengthParams p = entry_only(diameter, offset, entry, approach);
  entry_api::ExitSide side;
  side.contour = exit;
  side.length_mm = length;
  side.extra_path_mm = extra_path;
  side.overrun_mm = overrun;
  p.exit = side;
  return p;
}

// gtest-friendly description of a result's error state.
template <class T>
std::string outcome(const cutcalc::domain::Result<T>& result) {
  if (result.ok()) {
    return "ok";
  }
  return std::string(cutcalc::domain::error_code_name(result.error().code)) + ": " +
         result.error().detail;
}

// Main time, spec section 14: D = 50, z = 4, n = 1000, S_z = 0.1, f = 0.5, L = 120, L1 = 0,
// L_pod = L_per = 2, straight alpha = 90 entry and exit, B = 80; H1 = 80, t = 45, H = 5, t0 = 2.
inline entry_api::MainTimeParams main_time_worked_example() {
  entry_api::MainTimeParams p;
  p.cutter_diameter_mm = 50.0;
  p.teeth = 4;
  p.speed = entry_api::SpindleSpeed{1000.0};
  p.feed_per_tooth_mm = 0.1;
  p.entry_feed = entry_api::EntryFeedFactor{0.5};
  p.length_mm = 120.0;
  p.extra_path_mm = 0.0;
  p.approach_mm = 2.0;
  p.overrun_mm = 2.0;
  p.entry = straight_contour(80.0);
  p.exit = straight_contour(80.0);
  p.allowance = entry_api::Allowance{80.0, 45.0, 5.0, 2.0};
  return p;
}

// The main time of valid parameters (a test failure, and an empty result, otherwise).
inline entry_api::MainTimeResult main_time_ok(const entry_api::MainTimeParams& p) {
  const auto res = entry_api::compute_main_time(p);
  EXPECT_TRUE(res.ok()) << outcome(res);
  return res.ok() ? res.value() : entry_api::MainTimeResult{};
}

}  // namespace cutcalc::test
