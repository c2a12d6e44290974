#pragma once
// The pass program of spec programs.md section 1: the Vitebsk passes of a main-time computation
// (entry-and-main-time.md E24-E36) as a machine program, with the feed switching from S_m1 to S_m2
// exactly at the end of each entry section, and its times (G8-G11). Units: mm, mm/min, minutes.

#include <memory>
#include <string>
#include <vector>

#include "domain/common/result.h"
#include "domain/common/text_source.h"
#include "domain/entry/main_time.h"
#include "domain/program/program_model.h"
#include "domain/program/program_options.h"
#include "domain/program/program_size.h"

namespace cutcalc::domain::program {

struct PassProgram {
  // The program, LF line ends: its text is written as it is read (open_program_text).
  std::shared_ptr<const ProgramModel> model;
  ProgramOptions options;                 // what the text is written with
  std::string file_name;                  // section 3 table
  int passes = 0;                         // N1 x N2
  double working_time_min = 0.0;          // G8 (= main_time_min, E35)
  double plunge_time_min = 0.0;           // G9
  double rapid_time_min = 0.0;            // G10
  double cycle_time_min = 0.0;            // G11
  std::vector<std::string> not_modelled;  // what the times leave out
  std::vector<Warning> warnings;          // section 5 order
};

// G1-G11 on a computed main time. Precondition: params.extra_path_mm == 0 (L1 = 0, section 1.2: a
// program needs one straight path; the API refuses L1 > 0 as a field error). Errors:
// word_prints_as_zero (an F or S word), pass_program_too_large (over kMaxProgramBlocks; limit).
Result<PassProgram> write_pass_program(const entry::MainTimeParams& params,
                                       const entry::MainTimeResult& main_time,
                                       const ProgramOptions& options, const MachineLimits& limits);

// The program's text, written as it is read.
std::unique_ptr<TextSource> open_program_text(const PassProgram& program);
// The whole text of open_program_text.
std::string program_text(const PassProgram& program);

// The feeds a main-time setup uses (S_m1, S_m2, the finishing S_m1f and S_m2f; the program adds its
// plunge feeds), for the limit
// warnings of section 5.
std::vector<double> setup_feeds_mm_per_min(const entry::MainTimeResult& main_time);

// The fastest spindle speed a main-time setup uses (n, or the finishing n_f), for the warnings.
double setup_top_spindle_rpm(const entry::MainTimeResult& main_time);

}  // namespace cutcalc::domain::program
