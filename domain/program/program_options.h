#pragma once
// The `program` options shared by both machine programs (spec programs.md section 2), the machine
// limits that turn into warnings (section 5), and the warnings themselves. Units: mm, mm/min,
// rev/min; the program's own units are chosen by `units`.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "domain/program/program_warning.h"

namespace cutcalc::domain::program {

enum class Dialect { linuxcnc, fanuc, sinumerik };
enum class Units { mm, inch };
enum class Coolant { off, flood, mist };

// How the control runs through corners (machine-time.md section 7): stated by the line after the
// work offset, so that the machine runs what was timed and keeps the accuracy asked for.
enum class PathMode { exact_stop, exact_path, blend };
struct PathControl {
  PathMode mode = PathMode::blend;
  std::optional<double> tolerance_mm;  // blend only; absent: none (polygon: the fit tolerance)
};

inline constexpr double kMmPerInch = 25.4;
inline constexpr double kMPerFoot = 0.3048;  // G96 surface speed in ft/min under inch units
inline constexpr int kMinDecimals = 3;
inline constexpr int kMaxDecimals = 6;
inline constexpr int kMaxProgramNumber = 7999;  // O8000-O9999: edit-protected on many Fanucs
inline constexpr int kMaxToolNumber = 9999;
inline constexpr int kMaxTurretTool = 99;  // lathe: Fanuc T{tt}{oo} has two digits for each

struct ProgramOptions {
  Dialect dialect = Dialect::linuxcnc;
  Units units = Units::mm;
  std::optional<int> decimals;  // 3..6; absent: default_decimals(dialect, units)
  int program_number = 1;       // fanuc O number
  std::string name = "CUTCALC";
  std::optional<int> tool_number;  // writes the tool change
  bool tool_length_offset = false;
  int work_offset = 54;  // G54..G59
  Coolant coolant = Coolant::off;
  double safe_z_mm = 10.0;                       // retract height above Z0
  double clearance_mm = 2.0;                     // pass program: rapid to this above the level
  std::optional<double> plunge_feed_mm_per_min;  // pass program; absent: S_m1
  double rapid_mm_per_min = 10000.0;             // pass program: for the rapid time (G10)
  std::optional<PathControl> path_control;       // absent: the program names no mode (as before)
};

// linuxcnc 4 (mm) / 5 (inch); fanuc and sinumerik 3 / 4: their usual least input increment.
int default_decimals(Dialect dialect, Units units);
int decimals_of(const ProgramOptions& options);

// Why a string is not a program name (section 2).
enum class NameRule {
  shape,                      // 1..24 of A-Z, 0-9, _, starting with a letter
  reserved_device,            // CON, PRN, AUX, NUL, COM1-9, LPT1-9
  sinumerik_two_letters,      // sinumerik names start with two letters
  sinumerik_reserved_prefix,  // CYCLE, CUST_, GROUP_, S_, E_, F_, CC_
};
struct NameProblem {
  NameRule rule;
  std::string subject;  // the reserved name or prefix, when the rule has one
};

// Why `name` is not a program name for `dialect`, or nullopt when it is.
std::optional<NameProblem> name_problem(std::string_view name, Dialect dialect);
// The highest work offset the dialect has as a work offset (sinumerik G57; G58/G59 are
// programmable offsets there).
int max_work_offset(Dialect dialect);

std::string_view dialect_name(Dialect dialect);
std::string_view units_name(Units units);

// The program's file name (section 3 table).
std::string file_name(const ProgramOptions& options);

struct MachineLimits {
  std::optional<double> max_spindle_rpm;
  std::optional<double> max_feed_mm_per_min;
};

// A number in a warning's detail: 6 significant digits ("%.6g").
std::string number_text(double value);

// Section 5, warnings 1 and 2: n over the spindle limit; any of `feeds_mm_per_min` (exact values)
// over the feed limit.
std::vector<Warning> limit_warnings(double spindle_rpm, const std::vector<double>& feeds_mm_per_min,
                                    const MachineLimits& limits);

}  // namespace cutcalc::domain::program
