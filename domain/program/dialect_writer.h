#pragma once
// Writes a ProgramModel as the text of one dialect (spec programs.md sections 3 and 4): header,
// comment block, units and modal lines, work offset, the blocks, the end. Numbers are converted
// to the program's units and printed with `decimals` digits (never -0); G and M words, comments,
// the tool length offset and the S word take the dialect's form; an F word is written only when
// its printed value changes.

#include <optional>
#include <string>
#include <string_view>

#include "domain/program/program_model.h"
#include "domain/program/program_options.h"

namespace cutcalc::domain::program {

// printf("%.*f", decimals, value) without the sign of a value that prints as zero.
std::string format_fixed(double value, int decimals);

// A length or feed in the program's units (mm, or inch: / 25.4).
double to_program_units(double mm, Units units);

// The S word's number: fanuc an integer (round half up), the others with `decimals`.
std::string spindle_text(double rpm, Dialect dialect, int decimals);

// Section 3: the whole program text, LF line ends.
std::string write_program(const ProgramModel& model, const ProgramOptions& options);

// A comment line's text in the dialect's rules (fanuc: upper case; no parentheses, semicolons
// or percent signs inside any comment).
std::string comment_text(std::string_view text, Dialect dialect);

}  // namespace cutcalc::domain::program
