#include "api/machine_time/program_machine_time.h"

#include <algorithm>
#include <cstdio>
#include <memory>
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

// A program's text with `line` appended as append_line does, passed on piece by piece: the last
// bytes of each piece are held back until the end is known.
class WithLastLine final : public domain::TextSource {
 public:
  WithLastLine(std::unique_ptr<domain::TextSource> program, std::string line)
      : program_(std::move(program)), line_(std::move(line)) {}

  bool write_next(std::string& out, std::size_t max_bytes) override {
    if (!program_) return false;
    std::string piece = std::move(held_);
    held_.clear();
    if (program_->write_next(piece, max_bytes)) {
      const std::size_t keep = std::min<std::size_t>(piece.size(), 2);  // "%\n"
      held_.assign(piece, piece.size() - keep, keep);
      out.append(piece, 0, piece.size() - keep);
      return true;
    }
    program_.reset();
    append_line(piece, line_);
    out.append(piece);
    return false;
  }
  [[nodiscard]] std::size_t held_bytes() const override {
    return sizeof(*this) + line_.capacity() + held_.capacity() +
           (program_ ? program_->held_bytes() : 0);
  }

 private:
  std::unique_ptr<domain::TextSource> program_;
  std::string line_;
  std::string held_;
};

// The program of the JSON form, timed.
mt::ProgramTimeOutcome time_text(std::string_view text, const program::MachineRequest& machine,
                                 Dialect dialect) {
  mt::ProgramTimeParams params;
  params.program = text;
  params.read.dialect = dialect;
  params.read.kind = machine.kind;
  params.read.max_spindle_rpm = machine.limits.max_spindle_rpm.value_or(0.0);
  params.machine = *machine.timing;
  return mt::time_program(params);
}

}  // namespace

std::optional<Problem> add_machine_time(JsonWithText& answer,
                                        const program::MachineRequest& machine, Dialect dialect) {
  if (!machine.timing) return std::nullopt;
  // The time is known once the whole program is: the JSON form's program is written whole and
  // timed, then sent from that text; the text form is written again as it is sent (its own
  // comment lines differ), the time's line after it.
  std::string streamed_text;
  if (answer.program_source) domain::write_all(*answer.program_source, streamed_text);
  const std::string& text = answer.program_source
                                ? streamed_text
                                : answer.json.at("program").get_ref<const std::string&>();
  const mt::ProgramTimeOutcome outcome = time_text(text, machine, dialect);
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
  answer.json["machine_time"] = to_json(time);
  if (answer.program_source) {
    answer.program_source = std::make_unique<domain::StringSource>(std::move(streamed_text));
    answer.text_source =
        std::make_unique<WithLastLine>(std::move(answer.text_source), time_comment(time, dialect));
  } else {
    append_line(answer.text, time_comment(time, dialect));
  }
  return std::nullopt;
}

}  // namespace cutcalc::api::machine_time
