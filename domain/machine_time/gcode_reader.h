#pragma once
// Reads a G-code program into moves for the planner (spec machine-time.md section 4): the three
// dialects cutcalc writes (linuxcnc, fanuc, sinumerik), mm and inch, mills and lathes, and plain
// user programs of motion blocks. What cannot be timed without guessing is refused with the line,
// column and word, never approximated. Streaming: moves go to a sink as they are read, so a
// program of many MB holds no move list.

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <variant>

#include "domain/machine_time/move.h"
#include "domain/program/program_options.h"

namespace cutcalc::domain::machine_time {

enum class MachineKind { mill, lathe };

struct ReadOptions {
  program::Dialect dialect = program::Dialect::linuxcnc;
  MachineKind kind = MachineKind::mill;
  double max_spindle_rpm =
      0.0;  // the machine's; clamps G96 when the program states no clamp; 0: none
};

// Why a block cannot be timed.
enum class Refusal {
  parameter,            // #1=5, X#1, R-parameters (Sinumerik R1=)
  expression,           // [1+2], functions
  subroutine_or_loop,   // O-word sub/call/while/if, M98/M99, GOTO, L-calls, REPEAT
  cutter_compensation,  // G41/G42 (G41.1/G42.1)
  canned_cycle,      // G73-G89 drilling cycles, Fanuc lathe G90/G92/G94, G70-G76 (lathe), CYCLExx
  unsupported_word,  // a G/M code or letter the reader does not know; G64 Q
  malformed,         // a number that does not parse, a letter without a number, a word twice
  arc_geometry,      // an arc whose centre or radius does not fit its end points
  missing_feed,      // a feed move with no F in effect, G95 without a turning spindle
};

struct ReadError {
  Refusal refusal;
  std::size_t line = 0;    // 1-based
  std::size_t column = 0;  // 1-based, where the word starts
  std::string word;        // the word as written ("#1", "G41", "O100")
};

struct ReadSummary {
  std::size_t blocks = 0;     // lines that hold at least one word (comments and blank lines not)
  bool units_stated = false;  // G20/G21 (G70/G71, G700/G710) seen before the first move
  std::array<std::size_t, kAxisCount>
      first_line_moving{};  // per axis: first line moving it, 0: never
};

using MoveSink = std::function<void(const Move&)>;

std::variant<ReadSummary, ReadError> read_program(std::string_view text, const ReadOptions& options,
                                                  const MoveSink& sink);

}  // namespace cutcalc::domain::machine_time
