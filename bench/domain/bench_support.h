#pragma once
// Helpers shared by the domain benchmarks.

#include <cstdlib>
#include <iostream>

#include "domain/common/result.h"
#include "domain/polygon/polygon_hole.h"
#include "domain/program/program_options.h"

namespace cutcalc::bench {

// Aborts the benchmark program when a set-up calculation fails: a benchmark of an error path
// would measure the wrong thing.
template <class T>
void require_ok(const cutcalc::domain::Result<T>& result, const char* what) {
  if (!result.ok()) {
    std::cerr << what << ": unexpected error: " << result.error().detail << "\n";
    std::abort();
  }
}

// The largest polygon program the API allows: N = 3, d = 1 000 000 mm, a 0.1 um fit (m = 538,
// 3223 blocks per loop), 62 loops of c_axis, at 6 decimals (15.8 MB of text in Fanuc).
inline cutcalc::domain::polygon::PolygonHoleParams largest_polygon_program(
    cutcalc::domain::program::Dialect dialect) {
  cutcalc::domain::polygon::PolygonHoleParams params;
  params.faces = 3;
  params.inscribed_diameter_mm = 1e6;
  params.depth_mm = 1.0;
  params.step_down_mm = 1.0;
  params.spindle_speed_rpm = 30.0;
  params.tolerance_mm = 0.0001;
  params.loops_per_layer = 62;
  params.synchronization = cutcalc::domain::polygon::Synchronization::c_axis;
  cutcalc::domain::program::ProgramOptions options;
  options.dialect = dialect;
  options.decimals = 6;
  params.program = options;
  return params;
}

}  // namespace cutcalc::bench
