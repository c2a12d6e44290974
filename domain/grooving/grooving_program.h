#pragma once
// The lathe program of the "v razvod" cycle (spec grooving-cycle.md section 5): the blocks of
// K13-K14 and the pattern of K10, in one of three dialects, mm or inch.

#include <vector>

#include "domain/common/result.h"
#include "domain/grooving/grooving_cycle.h"
#include "domain/program/lathe_program.h"
#include "domain/program/program_options.h"

namespace cutcalc::domain::grooving {

struct GroovingProgram : program::LatheProgramFile {
  std::vector<program::Warning> warnings;  // the cycle's, then spindle_speed_rounded (Fanuc)
};

// Section 5.1-5.2. Errors: word_prints_as_zero (an F, S, D, LIMS or G50 S value, or a dwell with
// n_d > 0, that would print as zero).
Result<GroovingProgram> write_grooving_program(const GroovingCycleParams& params,
                                               const GroovingCycleResult& cycle,
                                               const program::ProgramOptions& options);

using program::open_program_text;
using program::program_text;

}  // namespace cutcalc::domain::grooving
