#pragma once
// Writes a ProgramModel as the text of one dialect (spec programs.md sections 3 and 4): header,
// comment block, units and modal lines, work offset, the blocks, the end. Numbers are converted
// to the program's units and printed with `decimals` digits (never -0); G and M words, comments,
// the tool length offset and the S word take the dialect's form; an F word is written only when
// its printed value changes.

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "domain/common/text_source.h"
#include "domain/program/program_model.h"
#include "domain/program/program_options.h"

namespace cutcalc::domain::program {

// The words each dialect writes for the same thing (section 3 table).
struct DialectWords {
  const char* rapid;        // G0 / G00
  const char* feed;         // G1 / G01
  const char* arc_ccw;      // G3 / G03
  const char* spindle_on;   // M3 / M03
  const char* spindle_off;  // M5 / M05
  const char* flood;        // M8 / M08
  const char* mist;         // M7 / M07
  const char* coolant_off;  // M9 / M09
  const char* tool_change;  // M6 / M06
};
const DialectWords& words_of(Dialect dialect);

// Section 3, the parts of a program around its body, each a run of whole lines: the start and
// name line, the comment lines, the units and modal lines and the work offset; the tool change
// and first move to the safe height; the end.
std::string program_header(const std::vector<std::string>& comments, const ProgramOptions& options);
// The first of them, the same for mills and lathes: the start and name line(s) and the comments.
std::string program_start(const std::vector<std::string>& comments, const ProgramOptions& options);
// "G54\n": the work offset line.
std::string work_offset_line(const ProgramOptions& options);
// The path control mode's line(s) (machine-time.md section 7), or "" when the program names none.
std::string path_control_lines(const ProgramOptions& options);
std::string safe_start_text(const SafeStart& start, const ProgramOptions& options);
std::string program_end(const ProgramOptions& options);

// printf("%.*f", decimals, value) without the sign of a value that prints as zero.
std::string format_fixed(double value, int decimals);

// A printed number that reads as zero ("0.000", "0"): a word a control would stop or refuse at.
bool prints_as_zero(std::string_view printed);

// A length or feed in the program's units (mm, or inch: / 25.4).
double to_program_units(double mm, Units units);

// A Fanuc S word takes no decimals (programs.md section 1.2): the value rounded half up.
double fanuc_s_value(double value);
// Whether the Fanuc S word changes `value` by more than 1e-9 (the warning spindle_speed_rounded).
bool fanuc_s_rounds(double value);

// The S word's number: fanuc an integer (fanuc_s_value), the others with `decimals`.
std::string spindle_text(double rpm, Dialect dialect, int decimals);

// Section 3: the program text of `model`, LF line ends, written as it is read (block by block).
std::unique_ptr<TextSource> open_program(std::shared_ptr<const ProgramModel> model,
                                         ProgramOptions options);
// The whole text of open_program.
std::string write_program(const ProgramModel& model, const ProgramOptions& options);
// What `model` holds, in bytes (for a memory budget).
std::size_t held_bytes(const ProgramModel& model);

// A comment line's text in the dialect's rules (fanuc: upper case; no parentheses, semicolons
// or percent signs inside any comment).
std::string comment_text(std::string_view text, Dialect dialect);

}  // namespace cutcalc::domain::program
