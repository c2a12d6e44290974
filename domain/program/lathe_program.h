#pragma once
// A lathe program (spec grooving-cycle.md section 5, and lathe-flat.md section 6 for the same
// dialect forms): XZ motion with X as a DIAMETER in every dialect (LinuxCNC G7, Fanuc T-series by
// default, Sinumerik DIAMON), feed per revolution, a spindle at constant speed or constant surface
// speed, dwells. Values are in mm, mm/rev, m/min, rev/min and seconds, unrounded; the writer
// converts them to the program's units and prints them in the dialect's words, from one table of
// lathe dialect facts (lathe_dialect.h).

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "domain/common/result.h"
#include "domain/common/text_source.h"
#include "domain/program/program_model.h"
#include "domain/program/program_options.h"

namespace cutcalc::domain::program {

struct LathePoint {
  LathePoint() = default;
  // Most lathe moves have no C word: {x, z} names them.
  LathePoint(std::optional<double> x, std::optional<double> z,
             std::optional<double> c = std::nullopt)
      : x_diameter_mm(x), z_mm(z), c_deg(c) {}

  std::optional<double> x_diameter_mm;  // X word: a diameter
  std::optional<double> z_mm;
  std::optional<double> c_deg;  // C word: the spindle as a rotary axis, degrees, never wrapped
};
struct LatheRapid {  // G0
  LathePoint to;
};
struct LatheFeed {  // G1 with F in mm per revolution (G95) or per minute (G94), as the mode is
  LathePoint to;
  double feed_mm = 0.0;
};
enum class FeedMode { per_minute, inverse_time };
struct FeedModeChange {  // G94 / G93; the next feed block writes its F again
  FeedMode mode = FeedMode::per_minute;
};
struct InverseTimeFeed {  // G1 under G93: F = 1/T per minute, in every block
  LathePoint to;
  double per_minute = 0.0;
};
struct ConstantSpindleSpeed {  // G97 S{n} M3
  double rpm = 0.0;
};
struct ConstantSurfaceSpeed {  // [G50 S{n_max}] G96 S{v} (LinuxCNC D, Sinumerik LIMS) M3
  double cutting_speed_m_per_min = 0.0;
  double max_rpm = 0.0;
};
struct Dwell {  // G4 with the time in seconds (P / X / F)
  double seconds = 0.0;
};

using LatheBlock =
    std::variant<LatheRapid, LatheFeed, FeedModeChange, InverseTimeFeed, ConstantSpindleSpeed,
                 ConstantSurfaceSpeed, Dwell, SpindleOff, CoolantOn, CoolantOff>;

// The modal line(s) after the name and comments, one form per dialect; "{units}" stands for the
// dialect's units word (G21/G20, Sinumerik G710/G700). Each program states its own.
struct LatheModalLines {
  const char* linuxcnc;
  const char* fanuc;
  const char* sinumerik;
};

struct LatheProgram {
  std::vector<std::string> comments;  // after the name line; written in the dialect's comment form
  LatheModalLines modal{};
  std::vector<LatheBlock> blocks;  // after the work offset and the tool call
};

// Dwell times are printed with 3 decimals in every dialect and unit (seconds).
inline constexpr int kDwellDecimals = 3;

// Error word_prints_as_zero when an F, S, D, LIMS or G50 S value, or a dwell, would print as zero
// (a control would stop the feed or the spindle, or reject the block): the first such word in the
// program's order; else nullopt. A program is checked before its text is opened.
std::optional<DomainError> lathe_program_error(const LatheProgram& program,
                                               const ProgramOptions& options);

// The text of a checked program (lathe_program_error), LF line ends, written as it is read (block
// by block). C words and inverse-time F are printed unconverted (degrees, 1/min) with `decimals`.
std::unique_ptr<TextSource> open_lathe_program(std::shared_ptr<const LatheProgram> program,
                                               ProgramOptions options);

// The check, then the whole text of open_lathe_program.
Result<std::string> write_lathe_program(const LatheProgram& program, const ProgramOptions& options);

// What `program` holds, in bytes (for a memory budget).
std::size_t held_bytes(const LatheProgram& program);

// A checked lathe program as it is sent: the grooving cycle's and the lathe flat's.
struct LatheProgramFile {
  // The program, LF line ends: its text is written as it is read (open_program_text).
  std::shared_ptr<const LatheProgram> program;
  ProgramOptions options;  // what the text is written with
  std::string file_name;
};

// `program` checked (lathe_program_error), then held with its options and file name.
Result<LatheProgramFile> lathe_program_file(LatheProgram program, const ProgramOptions& options);
// The program's text, written as it is read.
std::unique_ptr<TextSource> open_program_text(const LatheProgramFile& file);
// The whole text of open_program_text.
std::string program_text(const LatheProgramFile& file);

// The Fanuc S words of a spindle block: integers (v and n round half up; n_max floors, never above
// the limit); the values in the program's units (G96 in ft/min under G20).
struct FanucSpindleWords {
  double s = 0.0;                   // G96 S or G97 S
  std::optional<double> clamp_rpm;  // G50 S, with G96
  bool rounded = false;             // any of them differs from the exact value by more than 1e-9
};
FanucSpindleWords fanuc_spindle_words(const ConstantSpindleSpeed& spindle);
FanucSpindleWords fanuc_spindle_words(const ConstantSurfaceSpeed& spindle, Units units);

// The surface speed as written: m/min, or ft/min under inch units.
double surface_speed_in_program_units(double cutting_speed_m_per_min, Units units);

}  // namespace cutcalc::domain::program
