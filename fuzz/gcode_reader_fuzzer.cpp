// libFuzzer harness of the G-code reader (domain/machine_time/gcode_reader.h, spec machine-time.md
// section 4): arbitrary bytes as a program, read in every dialect on a mill and on a lathe.
//
// Oracle (abort on a broken promise, so libFuzzer keeps the input):
//  - no sanitizer report (ASan + UBSan);
//  - a refusal names a place in the program: line >= 1 and no further than the last line,
//    column >= 1 and within its line (one past its end for a word cut by the line end), and the
//    word as written, not empty;
//  - every move is finite (start, end, arc centre, feed, dwell), on a line of the program and on
//    no earlier line than the move before it; each starts where the one before it ended; dwells
//    and feeds are not negative, a feed move's feed is above zero;
//  - the summary counts no more blocks than the program has lines.
//
// Seeds: <seed dir>/gcode_reader/, written by cutcalc_fuzz_seeds (fuzz/make_seeds.cpp): programs
// the program endpoints write for reference requests in each dialect, and a few hand-written ones.

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <variant>

#include "domain/machine_time/gcode_reader.h"

namespace {

using cutcalc::domain::machine_time::AxisVector;
using cutcalc::domain::machine_time::MachineKind;
using cutcalc::domain::machine_time::Move;
using cutcalc::domain::machine_time::MoveKind;
using cutcalc::domain::machine_time::ReadError;
using cutcalc::domain::machine_time::ReadOptions;
using cutcalc::domain::machine_time::ReadSummary;
using cutcalc::domain::program::Dialect;

[[noreturn]] void broken(const char* promise, std::size_t line, std::size_t column) {
  std::fprintf(stderr, "gcode_reader_fuzzer: %s (line %zu, column %zu)\n", promise, line, column);
  std::abort();
}

bool finite(const AxisVector& v) {
  for (const double x : v) {
    if (!std::isfinite(x)) return false;
  }
  return true;
}

// The 1-based lines of the text, as the reader counts them (LF ends a line).
std::size_t line_count(std::string_view text) {
  std::size_t lines = 1;
  for (const char c : text) lines += c == '\n' ? 1 : 0;
  return lines;
}

std::size_t line_length(std::string_view text, std::size_t line) {
  std::size_t at = 0;
  for (std::size_t k = 1; k < line; ++k) at = text.find('\n', at) + 1;
  const std::size_t end = text.find('\n', at);
  return (end == std::string_view::npos ? text.size() : end) - at;
}

void check_move(const Move& move, const Move* previous, std::size_t lines) {
  if (move.line < 1 || move.line > lines) broken("move outside the program", move.line, 0);
  if (previous != nullptr && move.line < previous->line)
    broken("move line went back", move.line, 0);
  if (previous != nullptr && move.start != previous->end) {
    broken("move does not start where the one before ended", move.line, 0);
  }
  if (!finite(move.start) || !finite(move.end)) broken("non-finite position", move.line, 0);
  if (!std::isfinite(move.arc.centre[0]) || !std::isfinite(move.arc.centre[1])) {
    broken("non-finite arc centre", move.line, 0);
  }
  if (move.arc.extra_turns < 0) broken("negative turns", move.line, 0);
  const auto& feed = move.feed;
  for (const double value : {feed.value, feed.spindle_rpm, feed.surface_speed_m_per_min,
                             feed.max_spindle_rpm, move.blend_tolerance_mm, move.dwell_s}) {
    if (!std::isfinite(value) || value < 0.0) broken("non-finite or negative number", move.line, 0);
  }
  if ((move.kind == MoveKind::line || move.kind == MoveKind::arc) && !(feed.value > 0.0)) {
    broken("feed move without a feed", move.line, 0);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const std::size_t lines = line_count(text);
  static constexpr std::array<Dialect, 3> kDialects = {Dialect::linuxcnc, Dialect::fanuc,
                                                       Dialect::sinumerik};
  for (const Dialect dialect : kDialects) {
    for (const MachineKind kind : {MachineKind::mill, MachineKind::lathe}) {
      ReadOptions options;
      options.dialect = dialect;
      options.kind = kind;
      options.max_spindle_rpm = kind == MachineKind::lathe ? 3000.0 : 0.0;
      Move previous;
      bool any = false;
      const auto result =
          cutcalc::domain::machine_time::read_program(text, options, [&](const Move& move) {
            check_move(move, any ? &previous : nullptr, lines);
            previous = move;
            any = true;
          });
      if (const auto* error = std::get_if<ReadError>(&result)) {
        if (error->line < 1 || error->line > lines)
          broken("refusal outside the program", error->line, error->column);
        if (error->column < 1 || error->column > line_length(text, error->line) + 1) {
          broken("refusal outside its line", error->line, error->column);
        }
        if (error->word.empty()) broken("refusal without its word", error->line, error->column);
      } else if (std::get<ReadSummary>(result).blocks > lines) {
        broken("more blocks than lines", lines, 0);
      }
    }
  }
  return 0;
}
