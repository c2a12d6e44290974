#include "domain/lathe_flat/flat_program.h"

#include <utility>

#include "domain/common/ascii_text.h"
#include "domain/common/numeric.h"
#include "domain/program/dialect_writer.h"
#include "domain/program/lathe_program.h"

namespace cutcalc::domain::lathe_flat {
namespace {

using program::decimals_of;
using program::FeedMode;
using program::FeedModeChange;
using program::format_fixed;
using program::InverseTimeFeed;
using program::LatheBlock;
using program::LatheFeed;
using program::LatheModalLines;
using program::LatheProgram;
using program::LatheRapid;
using program::ProgramOptions;
using program::to_program_units;
using program::Warning;

constexpr LatheModalLines kModalLines{
    "{units} G18 G90 G40 G49 G80 G94 G7",
    "{units}\nG18 G40 G80 G90 G94",  // the candidate form; refused by the API (section 6.4)
    "G18 {units} G40 G90 G94 DIAMON",
};

std::string upper(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = ascii_upper(c);
  return out;
}

// F7, F22: flats outer, layers inner; each layer from its +alpha_e end.
std::vector<LatheBlock> blocks(const LatheFlatParams& params, const LatheFlatResult& flat) {
  const int n = flat.steps;
  std::vector<LatheBlock> out;
  out.reserve(static_cast<std::size_t>(flat.cut_blocks) + 6 * flat.layers * params.flats + 2);
  out.emplace_back(LatheRapid{{2.0 * flat.clear_x_mm, params.z_mm, std::nullopt}});
  for (int k = 0; k < params.flats; ++k) {
    const double flat_offset_deg = -k * 360.0 / params.flats;
    for (const FlatSection& layer : flat.layer_sections) {
      const double alpha_e = engagement_half_angle_rad(layer);
      out.emplace_back(LatheRapid{
          {std::nullopt, std::nullopt, flat_offset_deg + rad_times_180_over_pi(alpha_e)}});
      out.emplace_back(
          LatheFeed{{2.0 * tool_radius_position_mm(layer, alpha_e), std::nullopt, std::nullopt},
                    params.feed_mm_per_min});
      out.emplace_back(FeedModeChange{FeedMode::inverse_time});
      for (int i = 1; i <= 2 * n; ++i) {
        const double from = step_angle_rad(alpha_e, n, i - 1);
        const double to = step_angle_rad(alpha_e, n, i);
        const double block_min = chord_mm(layer, from, to) / params.feed_mm_per_min;  // T_i
        out.emplace_back(InverseTimeFeed{{2.0 * tool_radius_position_mm(layer, to), std::nullopt,
                                          flat_offset_deg + rad_times_180_over_pi(to)},
                                         1.0 / block_min});
      }
      out.emplace_back(FeedModeChange{FeedMode::per_minute});
      out.emplace_back(LatheRapid{{2.0 * flat.clear_x_mm, std::nullopt, std::nullopt}});
    }
  }
  return out;
}

// Every cutting block must move in its printed words: one whose X and C print as the previous
// block's would stand still for its 1/F under G93 (a flat too small for the program's decimals).
bool every_step_prints_a_move(const LatheFlatResult& flat, const ProgramOptions& options) {
  const int decimals = decimals_of(options);
  const int n = flat.steps;
  for (const FlatSection& layer : flat.layer_sections) {
    const double alpha_e = engagement_half_angle_rad(layer);
    std::string previous_x;
    std::string previous_c;
    for (int i = 0; i <= 2 * n; ++i) {
      const double alpha = step_angle_rad(alpha_e, n, i);
      const std::string x = format_fixed(
          to_program_units(2.0 * tool_radius_position_mm(layer, alpha), options.units), decimals);
      const std::string c = format_fixed(rad_times_180_over_pi(alpha), decimals);
      if (i > 0 && x == previous_x && c == previous_c) return false;
      previous_x = x;
      previous_c = c;
    }
  }
  return true;
}

}  // namespace

Result<FlatProgram> write_flat_program(const LatheFlatParams& params, const LatheFlatResult& flat,
                                       const ProgramOptions& options) {
  if (!every_step_prints_a_move(flat, options)) {
    return make_error(ErrorCode::steps_below_resolution);
  }
  LatheProgram program;
  program.modal = kModalLines;
  program.comments = {"CUTCALC LATHE FLAT",
                      "C AXIS: SPINDLE IN POSITION MODE AND DRIVEN TOOL RUNNING BEFORE THIS "
                      "PROGRAM, NOT WRITTEN HERE"};
  for (const Warning& warning : flat.warnings) {
    program.comments.push_back("WARNING " + upper(warning_name(warning.code)));
  }
  program.blocks = blocks(params, flat);
  return program::lathe_program_file(std::move(program), options);
}

}  // namespace cutcalc::domain::lathe_flat
