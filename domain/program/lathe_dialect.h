#pragma once
// The facts of the three dialects on a lathe (spec grooving-cycle.md section 5.2; lathe-flat.md
// section 6.4 shares them): one row per dialect, besides the milling words they share
// (dialect_writer.h words_of: G0/G00, M3/M03, ...). Fanuc is G-code system A, the factory default:
// there G90/G94 are turning cycles, G98/G99 choose the feed per minute/revolution, and G50 S clamps
// the spindle.

#include <string>

#include "domain/program/program_options.h"

namespace cutcalc::domain::program {

struct LatheDialectFacts {
  const char* metric_word;  // G21 / G710
  const char* inch_word;    // G20 / G700
  const char* dwell_word;   // "G4 P", "G04 X" (X with a decimal point: seconds), "G4 F": seconds
};

const LatheDialectFacts& lathe_facts(Dialect dialect);

// The units word of `options` (G21, G20, G710, G700).
const char* lathe_units_word(const ProgramOptions& options);

// The tool call line without its LF: "T7 M6 G43" (LinuxCNC: the tool's own length offset),
// "T0707" (Fanuc turret: tool 7, offset 7, no M06), "T7 D1" (Sinumerik: cutting edge 1).
std::string lathe_tool_call(int tool_number, Dialect dialect);

}  // namespace cutcalc::domain::program
