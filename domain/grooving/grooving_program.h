#pragma once
// The lathe program of the "v razvod" cycle (spec grooving-cycle.md section 5): the blocks of
// K13-K14 and the pattern of K10, in one of three dialects, mm or inch.

#include <memory>
#include <string>
#include <vector>

#include "domain/common/result.h"
#include "domain/common/text_source.h"
#include "domain/grooving/grooving_cycle.h"
#include "domain/program/lathe_program.h"
#include "domain/program/program_options.h"

namespace cutcalc::domain::grooving {

struct GroovingProgram {
  // The program, LF line ends: its text is written as it is read (open_program_text).
  std::shared_ptr<const program::LatheProgram> program;
  program::ProgramOptions options;  // what the text is written with
  std::string file_name;
  std::vector<program::Warning> warnings;  // the cycle's, then spindle_speed_rounded (Fanuc)
};

// Section 5.1-5.2. Errors: word_prints_as_zero (an F, S, D, LIMS or G50 S value, or a dwell with
// n_d > 0, that would print as zero).
Result<GroovingProgram> write_grooving_program(const GroovingCycleParams& params,
                                               const GroovingCycleResult& cycle,
                                               const program::ProgramOptions& options);

// The program's text, written as it is read.
std::unique_ptr<TextSource> open_program_text(const GroovingProgram& program);
// The whole text of open_program_text.
std::string program_text(const GroovingProgram& program);

}  // namespace cutcalc::domain::grooving
