#pragma once
// Spec programs.md section 4: P20 applied to the arcs of one loop as printed (start = the previous
// printed end, centre = start + (I, J), radius linear from start to end as LinuxCNC interpolates
// them, P23): the largest two-sided distance between those arcs and the exact centre path, mm.
// Private to domain/polygon.

#include <vector>

#include "domain/polygon/biarc_fit.h"
#include "domain/polygon/centre_path.h"
#include "domain/polygon/gcode_writer.h"

namespace cutcalc::domain::polygon::detail {

// `path` of unit diameter scaled by `d_mm`; `loop` printed from `blocks` in program units of
// `mm_per_unit` mm each.
double printed_path_deviation_mm(const CentrePath& path, double d_mm,
                                 const std::vector<LoopBlock>& blocks, const PrintedLoop& loop,
                                 double mm_per_unit);

}  // namespace cutcalc::domain::polygon::detail
