#include "domain/program/program_options.h"

#include <algorithm>
#include <array>
#include <cstdio>

namespace cutcalc::domain::program {
namespace {

bool is_upper(char c) { return c >= 'A' && c <= 'Z'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

std::string number_text(double value) {
  std::array<char, 64> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "%.6g", value);
  return buffer.data();
}

int default_decimals(Dialect dialect, Units units) {
  const int mm = dialect == Dialect::linuxcnc ? 4 : 3;
  return units == Units::inch ? mm + 1 : mm;
}

int decimals_of(const ProgramOptions& options) {
  return options.decimals.value_or(default_decimals(options.dialect, options.units));
}

std::optional<NameProblem> name_problem(std::string_view name, Dialect dialect) {
  const bool shaped = !name.empty() && name.size() <= 24 && is_upper(name.front()) &&
                      std::all_of(name.begin(), name.end(),
                                  [](char c) { return is_upper(c) || is_digit(c) || c == '_'; });
  if (!shaped) return NameProblem{NameRule::shape, {}};
  // Device names of the file systems the program may be copied through.
  for (const std::string_view reserved : {"CON", "PRN", "AUX", "NUL"}) {
    if (name == reserved) return NameProblem{NameRule::reserved_device, std::string(name)};
  }
  if (name.size() == 4 && (name.substr(0, 3) == "COM" || name.substr(0, 3) == "LPT") &&
      name[3] >= '1' && name[3] <= '9') {
    return NameProblem{NameRule::reserved_device, std::string(name)};
  }
  if (dialect == Dialect::sinumerik) {
    if (name.size() < 2 || !is_upper(name[1])) {
      return NameProblem{NameRule::sinumerik_two_letters, {}};
    }
    for (const std::string_view prefix : {"CYCLE", "CUST_", "GROUP_", "S_", "E_", "F_", "CC_"}) {
      if (name.substr(0, prefix.size()) == prefix) {
        return NameProblem{NameRule::sinumerik_reserved_prefix, std::string(prefix)};
      }
    }
  }
  return std::nullopt;
}

int max_work_offset(Dialect dialect) { return dialect == Dialect::sinumerik ? 57 : 59; }

std::string_view dialect_name(Dialect dialect) {
  switch (dialect) {
    case Dialect::fanuc:
      return "fanuc";
    case Dialect::sinumerik:
      return "sinumerik";
    case Dialect::linuxcnc:
      break;
  }
  return "linuxcnc";
}

std::string_view units_name(Units units) { return units == Units::inch ? "inch" : "mm"; }

std::string file_name(const ProgramOptions& options) {
  switch (options.dialect) {
    case Dialect::fanuc: {
      std::array<char, 16> number{};
      std::snprintf(number.data(), number.size(), "O%04d.nc", options.program_number);
      return number.data();
    }
    case Dialect::sinumerik:
      return options.name + ".MPF";
    case Dialect::linuxcnc:
      break;
  }
  return options.name + ".ngc";
}

std::vector<Warning> limit_warnings(double spindle_rpm, const std::vector<double>& feeds_mm_per_min,
                                    const MachineLimits& limits) {
  std::vector<Warning> warnings;
  if (limits.max_spindle_rpm && spindle_rpm > *limits.max_spindle_rpm) {
    warnings.push_back(
        {WarningCode::spindle_over_limit, "spindle speed " + number_text(spindle_rpm) +
                                              " rpm is above the machine's " +
                                              number_text(*limits.max_spindle_rpm) + " rpm"});
  }
  if (limits.max_feed_mm_per_min && !feeds_mm_per_min.empty()) {
    const double highest = *std::max_element(feeds_mm_per_min.begin(), feeds_mm_per_min.end());
    if (highest > *limits.max_feed_mm_per_min) {
      warnings.push_back({WarningCode::feed_over_limit,
                          "feed " + number_text(highest) + " mm/min is above the machine's " +
                              number_text(*limits.max_feed_mm_per_min) + " mm/min"});
    }
  }
  return warnings;
}

}  // namespace cutcalc::domain::program
