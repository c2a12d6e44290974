#pragma once
// A warning of a machine program (both the pass program and the polygon program): its code from
// the one list (domain/program/warning_codes.def) and its detail, which is also written into the
// program as a comment line.

#include <cstddef>
#include <string>
#include <string_view>

namespace cutcalc::domain::program {

enum class WarningCode {
#define CUTCALC_PROGRAM_WARNING(name) name,
#include "domain/program/warning_codes.def"
#undef CUTCALC_PROGRAM_WARNING
};

// The wire name of `code` ("spindle_over_limit").
constexpr std::string_view warning_name(WarningCode code) {
  constexpr std::string_view kNames[] = {
#define CUTCALC_PROGRAM_WARNING(name) #name,
#include "domain/program/warning_codes.def"
#undef CUTCALC_PROGRAM_WARNING
  };
  return kNames[static_cast<std::size_t>(code)];
}

struct Warning {
  WarningCode code;
  std::string detail;  // English with the numbers: a comment line of the program too
};

// "WARNING spindle_over_limit: spindle speed ...": the warning as a program comment's text.
inline std::string comment_text(const Warning& warning) {
  std::string text = "WARNING ";
  text += warning_name(warning.code);
  text += ": ";
  text += warning.detail;
  return text;
}

}  // namespace cutcalc::domain::program
