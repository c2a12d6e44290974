#pragma once
// The program of a flat milled on a lathe (spec lathe-flat.md section 6, F22): C steps with X
// following under G93 inverse time, so that every cutting block carries its own duration and the
// program's time is the model's; X as a diameter; LinuxCNC and Sinumerik (a Fanuc form with an
// exact time is not established: the API refuses it).

#include "domain/common/result.h"
#include "domain/lathe_flat/lathe_flat.h"
#include "domain/program/lathe_program.h"
#include "domain/program/program_options.h"

namespace cutcalc::domain::lathe_flat {

using FlatProgram = program::LatheProgramFile;

// Section 6.2. Errors: word_prints_as_zero (an F that would print as zero), steps_below_resolution
// (a cutting block whose X and C print as the previous block's: it would stand still for its 1/F).
Result<FlatProgram> write_flat_program(const LatheFlatParams& params, const LatheFlatResult& flat,
                                       const program::ProgramOptions& options);

using program::open_program_text;
using program::program_text;

}  // namespace cutcalc::domain::lathe_flat
