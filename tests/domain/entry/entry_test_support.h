#pragma once
// Builders for entry-length / main-time parameters used by the domain tests.

#include <optional>
#include <string>

#include "domain/common/result.h"
#include "domain/entry/contour.h"
#include "domain/entry/entry_length.h"
#include "domain/entry/main_time.h"

namespace cutcalc::test {

namespace entry_api = cutcalc::domain::entry;

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

}  // namespace cutcalc::test
