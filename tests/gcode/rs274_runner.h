#pragma once
// Runs LinuxCNC's stand-alone interpreter on a program, as the acceptance gate of spec
// polygon-holes.md section 9 does: `rs274 -i strict.ini -g FILE.ngc </dev/null`, strict.ini holding
// `[RS274NGC]` / `CENTER_ARC_RADIUS_TOLERANCE_MM = 0.001` (the strictest value rs274 honours).

#include <string>

namespace cutcalc::test::gcode {

// The strict.ini written next to every program.
inline constexpr const char* kStrictIni = "[RS274NGC]\nCENTER_ARC_RADIUS_TOLERANCE_MM = 0.001\n";

// rs274 prints canonical arguments with 4 decimals, in the units of the program.
inline constexpr double kCanonStep = 1e-4;
inline constexpr double kMmPerInch = 25.4;

struct Rs274Run {
  bool started = false;    // false: rs274 could not be run (spawn_error says why)
  int exit_code = -1;      // 0 = accepted; 128 + signal when killed by a signal
  bool timed_out = false;  // killed after the time limit
  std::string output;      // stdout: the canonical commands
  std::string errors;      // stderr: the rejection message, if any
  std::string spawn_error;
};

// The executable from the build (CUTCALC_RS274, set by CMake's find_program), else "rs274" on PATH.
std::string rs274_executable();

// Writes FILE.ngc and strict.ini into a fresh mkdtemp directory, runs rs274 there with stdin from
// /dev/null, collects stdout, stderr and the exit status, and removes the directory.
Rs274Run run_rs274(const std::string& program_text,
                   const std::string& executable = rs274_executable(), int timeout_s = 120);

// The same with a tool table (`-t tool.tbl`, LinuxCNC format: `T7 P7 ;`), for programs that
// change tools (`T7 M6`): rs274 refuses a tool the table lacks.
Rs274Run run_rs274_with_tools(const std::string& program_text, const std::string& tool_table);

}  // namespace cutcalc::test::gcode
