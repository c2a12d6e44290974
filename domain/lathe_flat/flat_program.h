#pragma once
// The program of a flat milled on a lathe (spec lathe-flat.md section 6, F22): C steps with X
// following under G93 inverse time, so that every cutting block carries its own duration and the
// program's time is the model's; X as a diameter; LinuxCNC and Sinumerik (a Fanuc form with an
// exact time is not established: the API refuses it).

#include <memory>
#include <string>
#include <vector>

#include "domain/common/result.h"
#include "domain/common/text_source.h"
#include "domain/lathe_flat/lathe_flat.h"
#include "domain/program/lathe_program.h"
#include "domain/program/program_options.h"

namespace cutcalc::domain::lathe_flat {

struct FlatProgram {
  // The program, LF line ends: its text is written as it is read (open_program_text).
  std::shared_ptr<const program::LatheProgram> program;
  program::ProgramOptions options;  // what the text is written with
  std::string file_name;
};

// Section 6.2. Errors: word_prints_as_zero (an F that would print as zero), steps_below_resolution
// (a cutting block whose X and C print as the previous block's: it would stand still for its 1/F).
Result<FlatProgram> write_flat_program(const LatheFlatParams& params, const LatheFlatResult& flat,
                                       const program::ProgramOptions& options);

// The program's text, written as it is read.
std::unique_ptr<TextSource> open_program_text(const FlatProgram& program);
// The whole text of open_program_text.
std::string program_text(const FlatProgram& program);

}  // namespace cutcalc::domain::lathe_flat
