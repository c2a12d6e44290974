#include "domain/grooving/grooving_program.h"

#include <utility>

#include "domain/program/lathe_program.h"

namespace cutcalc::domain::grooving {
namespace {

using program::ConstantSpindleSpeed;
using program::ConstantSurfaceSpeed;
using program::Coolant;
using program::CoolantOff;
using program::CoolantOn;
using program::Dialect;
using program::Dwell;
using program::fanuc_spindle_words;
using program::LatheBlock;
using program::LatheFeed;
using program::LatheModalLines;
using program::LatheProgram;
using program::LatheRapid;
using program::ProgramOptions;
using program::SpindleOff;
using program::Units;
using program::Warning;
using program::WarningCode;

constexpr LatheModalLines kModalLines{
    "{units} G18 G7 G90 G40 G49 G80 G95",  // G7: X is a diameter; G95: feed per revolution
    "{units}\nG18 G40 G99",  // system A: no G90 (a turning cycle there); G99 = per rev
    "G18 {units} G40 G90 G95 DIAMON",
};

LatheBlock spindle_block(const SpindleMode& spindle) {
  if (spindle.spindle_speed_rpm) return ConstantSpindleSpeed{*spindle.spindle_speed_rpm};
  return ConstantSurfaceSpeed{*spindle.cutting_speed_m_per_min, *spindle.max_spindle_rpm};
}

bool fanuc_rounds(const LatheBlock& spindle, Units units) {
  if (const auto* css = std::get_if<ConstantSurfaceSpeed>(&spindle)) {
    return fanuc_spindle_words(*css, units).rounded;
  }
  return fanuc_spindle_words(std::get<ConstantSpindleSpeed>(spindle)).rounded;
}

// K13, K10, K14.
std::vector<LatheBlock> blocks(const GroovingCycleParams& params, const GroovingCycleResult& cycle,
                               const LatheBlock& spindle, const ProgramOptions& options) {
  const double s = cycle.infeed_per_revolution_mm;
  std::vector<LatheBlock> out;
  out.reserve(cycle.pattern.size() + 10);
  out.emplace_back(LatheRapid{{cycle.approach_diameter_mm, params.groove_left_z_mm}});
  out.push_back(spindle);
  if (options.coolant != Coolant::off) out.emplace_back(CoolantOn{options.coolant});
  out.emplace_back(LatheFeed{{params.start_diameter_mm, std::nullopt}, s});
  for (const PatternBlock& block : cycle.pattern) {
    if (block.shifts) {
      out.emplace_back(LatheFeed{{block.diameter_mm, side_z_mm(params, cycle, block.side)},
                                 cycle.shift_feed_mm_per_rev});
    } else {
      out.emplace_back(LatheFeed{{block.diameter_mm, std::nullopt}, s});
    }
  }
  if (params.dwell_revolutions > 0.0) out.emplace_back(Dwell{cycle.dwell_seconds});
  out.emplace_back(LatheFeed{{std::nullopt, side_z_mm(params, cycle, cycle.end_side)}, s});
  out.emplace_back(LatheRapid{{cycle.approach_diameter_mm, std::nullopt}});
  out.emplace_back(SpindleOff{});
  if (options.coolant != Coolant::off) out.emplace_back(CoolantOff{});
  return out;
}

}  // namespace

Result<GroovingProgram> write_grooving_program(const GroovingCycleParams& params,
                                               const GroovingCycleResult& cycle,
                                               const ProgramOptions& options) {
  std::vector<Warning> warnings = cycle.warnings;
  const LatheBlock spindle = spindle_block(params.spindle);
  if (options.dialect == Dialect::fanuc && fanuc_rounds(spindle, options.units)) {
    warnings.push_back({WarningCode::spindle_speed_rounded,
                        "a Fanuc S word takes no decimals: v and n are rounded half up, the "
                        "G50 limit down (times use the exact values)"});
  }
  LatheProgram program;
  program.modal = kModalLines;
  program.comments.emplace_back("CUTCALC GROOVING CYCLE V RAZVOD");
  for (const Warning& warning : warnings) {
    program.comments.emplace_back(warning_name(warning.code));
  }
  program.blocks = blocks(params, cycle, spindle, options);
  auto file = program::lathe_program_file(std::move(program), options);
  if (!file.ok()) return file.error();
  return GroovingProgram{std::move(file.value()), std::move(warnings)};
}

}  // namespace cutcalc::domain::grooving
