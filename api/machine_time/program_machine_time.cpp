#include "api/machine_time/program_machine_time.h"

#include <cstdio>
#include <stdexcept>
#include <string>

#include "api/machine_time/machine_time_json.h"
#include "domain/machine_time/program_time.h"

namespace cutcalc::api::machine_time {
namespace {

namespace mt = domain::machine_time;
using domain::program::Dialect;

// "(MACHINE TIME 1.234 MIN ON THIS MACHINE, NOMINAL 1.000 MIN)" in the dialect's comment form;
// upper case and ASCII, as every other comment line (controls may not show lower case or
// Cyrillic).
std::string time_comment(const mt::ProgramTime& time, Dialect dialect) {
  char text[160];
  std::snprintf(text, sizeof text, "MACHINE TIME %.3f MIN ON THIS MACHINE, NOMINAL %.3f MIN",
                time.estimated_s / 60.0, time.nominal_s / 60.0);
  // Appended: GCC 12's -Wrestrict misfires on "literal" + std::string at -O3.
  std::string line = dialect == Dialect::sinumerik ? "; " : "(";
  line.append(text);
  if (dialect != Dialect::sinumerik) line.append(")");
  return line;
}

// The comment goes last, but inside a Fanuc tape's closing '%'.
void append_line(std::string& program, const std::string& line) {
  if (program.ends_with("%\n")) {
    std::string with_end = line;
    with_end.append("\n");
    program.insert(program.size() - 2, with_end);
  } else {
    if (!program.empty() && program.back() != '\n') program += '\n';
    program.append(line).append("\n");
  }
}

}  // namespace

std::optional<Problem> add_machine_time(JsonWithText& answer,
                                        const program::MachineRequest& machine, Dialect dialect) {
  if (!machine.timing) return std::nullopt;
  // The time is known once the whole program is: it is written at once here, not as it is sent.
  write_whole(answer);
  const std::string& text = answer.json.at("program").get_ref<const std::string&>();
  mt::ProgramTimeParams params;
  params.program = text;
  params.read.dialect = dialect;
  params.read.kind = machine.kind;
  params.read.max_spindle_rpm = machine.limits.max_spindle_rpm.value_or(0.0);
  params.machine = *machine.timing;
  const mt::ProgramTimeOutcome outcome = mt::time_program(params);
  if (const auto* missing = std::get_if<mt::AxisNotDescribed>(&outcome)) {
    return to_problem(*missing);
  }
  if (const auto* refused = std::get_if<mt::ReadError>(&outcome)) {
    // cutcalc's own programs are always read back (tests/api/program_readback_test.cpp).
    std::string what = "a program cutcalc wrote was refused at line ";
    what.append(std::to_string(refused->line)).append(": ").append(refused->word);
    throw std::logic_error(what);
  }
  const auto& time = std::get<mt::ProgramTime>(outcome);
  append_line(answer.text, time_comment(time, dialect));
  answer.json["machine_time"] = to_json(time);
  return std::nullopt;
}

}  // namespace cutcalc::api::machine_time
