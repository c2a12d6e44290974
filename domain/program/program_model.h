#pragma once
// One program model for every dialect (spec programs.md section 3): the motion and machine
// functions of a program, in mm and mm/min, unrounded. A dialect writer (dialect_writer.h) only
// chooses the words around them, so the motion is the same in every dialect by construction.

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "domain/program/program_options.h"

namespace cutcalc::domain::program {

struct Axes {
  std::optional<double> x_mm;
  std::optional<double> y_mm;
  std::optional<double> z_mm;
};

// [tool change], then the first move to the safe height with the tool length offset if asked:
// the one block whose words differ most between dialects (G43 H / D1).
struct SafeStart {
  std::optional<int> tool_number;
  bool tool_length_offset = false;
  double safe_z_mm = 0.0;
};
struct Rapid {  // G0
  Axes to;
};
struct Feed {  // G1, F in mm/min
  Axes to;
  double feed_mm_per_min = 0.0;
};
struct SpindleOn {  // S M3
  double rpm = 0.0;
};
struct SpeedChange {  // S alone: a new speed while the spindle turns (the finishing level's n_f)
  double rpm = 0.0;
};
struct SpindleOff {};  // M5
struct CoolantOn {     // M8 / M7
  Coolant coolant = Coolant::flood;
};
struct CoolantOff {};  // M9

using Block =
    std::variant<SafeStart, Rapid, Feed, SpindleOn, SpeedChange, SpindleOff, CoolantOn, CoolantOff>;

struct ProgramModel {
  std::vector<std::string> comments;  // the comment block after the name line, warnings last
  std::vector<Block> blocks;          // between the dialect's header and its end
};

}  // namespace cutcalc::domain::program
