#include "domain/program/lathe_dialect.h"

#include <array>
#include <cstdio>

namespace cutcalc::domain::program {

const LatheDialectFacts& lathe_facts(Dialect dialect) {
  static constexpr LatheDialectFacts kLinuxcnc{"G21", "G20", "G4 P"};
  static constexpr LatheDialectFacts kFanuc{"G21", "G20", "G04 X"};
  static constexpr LatheDialectFacts kSinumerik{"G710", "G700", "G4 F"};
  switch (dialect) {
    case Dialect::fanuc:
      return kFanuc;
    case Dialect::sinumerik:
      return kSinumerik;
    case Dialect::linuxcnc:
      break;
  }
  return kLinuxcnc;
}

const char* lathe_units_word(const ProgramOptions& options) {
  const LatheDialectFacts& facts = lathe_facts(options.dialect);
  return options.units == Units::inch ? facts.inch_word : facts.metric_word;
}

std::string lathe_tool_call(int tool_number, Dialect dialect) {
  std::array<char, 32> line{};
  switch (dialect) {
    case Dialect::fanuc:
      std::snprintf(line.data(), line.size(), "T%02d%02d", tool_number, tool_number);
      break;
    case Dialect::sinumerik:
      std::snprintf(line.data(), line.size(), "T%d D1", tool_number);
      break;
    case Dialect::linuxcnc:
      std::snprintf(line.data(), line.size(), "T%d M6 G43", tool_number);
      break;
  }
  return line.data();
}

}  // namespace cutcalc::domain::program
