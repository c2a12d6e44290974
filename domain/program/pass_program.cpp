// Spec programs.md section 1: frame G1-G3, passes G4-G7, block sequence, times G8-G11; the
// levels' own feeds and speed of entry-and-main-time.md section 15 (E41).

#include "domain/program/pass_program.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

#include "domain/common/numeric.h"
#include "domain/program/dialect_writer.h"
#include "domain/program/program_model.h"

namespace cutcalc::domain::program {
namespace {

using entry::ContourKind;

// One traverse (G5-G7), program coordinates in mm.
struct Traverse {
  double x_start_mm = 0.0;      // X_s,i
  double x_entry_end_mm = 0.0;  // X_v,i: end of the reduced feed
  double x_end_mm = 0.0;        // X_e,i: end of the stroke
  double y_mm = 0.0;            // Y_i
};

// G5-G7.
std::vector<Traverse> traverses(const entry::MainTimeParams& params,
                                const entry::MainTimeResult& main_time) {
  const std::size_t lateral = main_time.lateral_passes.size();
  const bool strips = params.entry.kind == ContourKind::straight && lateral > 1;
  const double cot_alpha = cot_deg(params.entry.angle_deg);  // 0 exactly at 90 deg
  std::vector<Traverse> out;
  out.reserve(lateral);
  for (std::size_t i = 0; i < lateral; ++i) {
    const entry::LateralPass& pass = main_time.lateral_passes[i];
    Traverse t;
    const double strip_side_mm = pass.lower_boundary_mm;  // Y_(i-1) (E27, E38)
    t.x_start_mm = (strips ? strip_side_mm * cot_alpha : 0.0) - pass.start.x_mm;
    t.x_entry_end_mm = t.x_start_mm + pass.entry_length_mm;
    t.x_end_mm = t.x_start_mm + pass.working_stroke_mm;
    t.y_mm = pass.axis_y_mm;
    out.push_back(t);
  }
  return out;
}

// One depth level (G4) and the feeds it runs at: the roughing ones (E30-E33), or the finishing
// level's (E40: its own S_m1f, S_m2f, n_f; its default plunge feed is S_m1f).
struct Level {
  double depth_mm = 0.0;     // d_j
  double spindle_rpm = 0.0;  // n or n_f
  double entry_feed = 0.0;   // S_m1,j
  double steady_feed = 0.0;  // S_m2,j
  double plunge_feed = 0.0;  // the request's, else S_m1,j
};

std::vector<Level> levels_of(const entry::MainTimeResult& main_time,
                             const ProgramOptions& options) {
  std::vector<Level> out;
  out.reserve(main_time.depth_passes_mm.size());
  for (const double depth : main_time.depth_passes_mm) {
    out.push_back({depth, main_time.spindle_speed_rpm, main_time.entry_feed_mm_per_min,
                   main_time.feed_mm_per_min,
                   options.plunge_feed_mm_per_min.value_or(main_time.entry_feed_mm_per_min)});
  }
  if (main_time.finish) {
    const entry::FinishLevel& finish = *main_time.finish;
    out.back() = {finish.depth_mm, finish.spindle_speed_rpm, finish.entry_feed_mm_per_min,
                  finish.feed_mm_per_min,
                  options.plunge_feed_mm_per_min.value_or(finish.entry_feed_mm_per_min)};
  }
  return out;
}

double distance(const Axes& a, const Axes& b) {
  return std::hypot(a.x_mm.value_or(0.0) - b.x_mm.value_or(0.0),
                    a.y_mm.value_or(0.0) - b.y_mm.value_or(0.0),
                    a.z_mm.value_or(0.0) - b.z_mm.value_or(0.0));
}

std::string header_comment(const entry::MainTimeResult& main_time, std::size_t passes,
                           const ProgramOptions& options) {
  const int decimals = decimals_of(options);
  return "N1 X N2 = " + std::to_string(main_time.lateral_passes.size()) + " X " +
         std::to_string(main_time.depth_passes_mm.size()) + " = " + std::to_string(passes) +
         " PASSES, MAIN TIME " + format_fixed(main_time.main_time_min, decimals) + " MIN";
}

}  // namespace

std::vector<double> setup_feeds_mm_per_min(const entry::MainTimeResult& main_time) {
  std::vector<double> feeds = {main_time.entry_feed_mm_per_min, main_time.feed_mm_per_min};
  if (main_time.finish) {
    feeds.push_back(main_time.finish->entry_feed_mm_per_min);
    feeds.push_back(main_time.finish->feed_mm_per_min);
  }
  return feeds;
}

double setup_top_spindle_rpm(const entry::MainTimeResult& main_time) {
  return main_time.finish
             ? std::max(main_time.spindle_speed_rpm, main_time.finish->spindle_speed_rpm)
             : main_time.spindle_speed_rpm;
}

Result<PassProgram> write_pass_program(const entry::MainTimeParams& params,
                                       const entry::MainTimeResult& main_time,
                                       const ProgramOptions& options, const MachineLimits& limits) {
  const std::vector<Traverse> passes = traverses(params, main_time);
  const std::size_t levels = main_time.depth_passes_mm.size();
  const double blocks =
      17.0 + 6.0 * static_cast<double>(passes.size()) * static_cast<double>(levels);
  if (blocks > kMaxProgramBlocks) {
    return make_limit_error(ErrorCode::pass_program_too_large, kMaxProgramBlocks);
  }

  const double n = main_time.spindle_speed_rpm;
  const std::vector<Level> levels_to_cut = levels_of(main_time, options);
  const int decimals = decimals_of(options);
  for (const Level& level : levels_to_cut) {
    for (const double feed : {level.plunge_feed, level.entry_feed, level.steady_feed}) {
      if (prints_as_zero(format_fixed(to_program_units(feed, options.units), decimals))) {
        return make_error(ErrorCode::word_prints_as_zero,
                          "a feed is too small to print with this many decimals");
      }
    }
    if (prints_as_zero(spindle_text(level.spindle_rpm, options.dialect, decimals))) {
      return make_error(ErrorCode::word_prints_as_zero,
                        "the spindle speed is too small to print with this many decimals");
    }
  }

  PassProgram out;
  out.passes = static_cast<int>(passes.size() * levels);
  std::vector<double> feeds = setup_feeds_mm_per_min(main_time);
  std::vector<double> speeds = {n};
  for (const Level& level : levels_to_cut) feeds.push_back(level.plunge_feed);
  if (main_time.finish && main_time.finish->spindle_speed_rpm != n) {
    speeds.push_back(main_time.finish->spindle_speed_rpm);
  }
  out.warnings = limit_warnings(setup_top_spindle_rpm(main_time), feeds, limits);
  if (options.dialect == Dialect::fanuc) {
    for (const double rpm : speeds) {
      if (fanuc_s_rounds(rpm)) {
        out.warnings.push_back(
            {WarningCode::spindle_speed_rounded,
             "a Fanuc S word takes no decimals: S" + spindle_text(rpm, options.dialect, decimals) +
                 " for n = " + format_fixed(rpm, 6) + " rpm (feeds and times use the exact n)"});
      }
    }
  }

  auto written = std::make_shared<ProgramModel>();
  ProgramModel& model = *written;
  model.comments = {
      "CUTCALC PASS PROGRAM", header_comment(main_time, passes.size() * levels, options),
      std::string("PROGRAM UNITS ") + (options.units == Units::inch ? "INCH" : "MM") +
          ", X ALONG THE FEED FROM THE ENTRY EDGE, Y FROM THE SIDE EDGE, Z0 TOP FACE"};
  if (main_time.finish) {
    model.comments.push_back("LAST DEPTH LEVEL: FINISHING, AT ITS OWN FEEDS AND SPINDLE SPEED");
  }
  for (const Warning& warning : out.warnings) {
    model.comments.push_back(comment_text(warning));
  }

  model.blocks.reserve(static_cast<std::size_t>(blocks));
  model.blocks.emplace_back(
      SafeStart{options.tool_number, options.tool_length_offset, options.safe_z_mm});
  model.blocks.emplace_back(SpindleOn{n});
  if (options.coolant != Coolant::off) model.blocks.emplace_back(CoolantOn{options.coolant});

  double z_level = 0.0;  // Z_(j-1)
  double rapid_mm = 0.0;
  double spindle_rpm = n;  // the speed the spindle turns at
  Axes at;                 // where the tool is, after the first G0 X Y
  bool positioned = false;
  for (const Level& level : levels_to_cut) {
    const double z = z_level - level.depth_mm;  // G4
    if (level.spindle_rpm != spindle_rpm) {
      // Section 15: the finishing level's own n_f, set at the safe height before its passes.
      model.blocks.emplace_back(SpeedChange{level.spindle_rpm});
      spindle_rpm = level.spindle_rpm;
    }
    for (const Traverse& t : passes) {
      const Axes above{t.x_start_mm, t.y_mm, options.safe_z_mm};
      if (positioned) rapid_mm += distance(at, above);
      positioned = true;
      model.blocks.emplace_back(Rapid{{t.x_start_mm, t.y_mm, std::nullopt}});
      const double approach_z = z_level + options.clearance_mm;
      rapid_mm += options.safe_z_mm - approach_z;
      model.blocks.emplace_back(Rapid{{std::nullopt, std::nullopt, approach_z}});
      model.blocks.emplace_back(Feed{{std::nullopt, std::nullopt, z}, level.plunge_feed});
      out.plunge_time_min += (approach_z - z) / level.plunge_feed;  // G9
      model.blocks.emplace_back(
          Feed{{t.x_entry_end_mm, std::nullopt, std::nullopt}, level.entry_feed});
      const std::string entry_end =
          format_fixed(to_program_units(t.x_entry_end_mm, options.units), decimals);
      const std::string stroke_end =
          format_fixed(to_program_units(t.x_end_mm, options.units), decimals);
      if (stroke_end != entry_end) {
        model.blocks.emplace_back(
            Feed{{t.x_end_mm, std::nullopt, std::nullopt}, level.steady_feed});
      }
      model.blocks.emplace_back(Rapid{{std::nullopt, std::nullopt, options.safe_z_mm}});
      rapid_mm += options.safe_z_mm - z;
      at = Axes{t.x_end_mm, t.y_mm, options.safe_z_mm};
    }
    z_level = z;
  }
  model.blocks.emplace_back(SpindleOff{});
  if (options.coolant != Coolant::off) model.blocks.emplace_back(CoolantOff{});

  // G8 = E41: the passes' own feed times at each level's feeds, summed over the depth levels, are
  // the main time.
  for (const Level& level : levels_to_cut) {
    for (const entry::LateralPass& pass : main_time.lateral_passes) {
      out.working_time_min += pass.entry_length_mm / level.entry_feed +
                              (pass.working_stroke_mm - pass.entry_length_mm) / level.steady_feed;
    }
  }
  out.rapid_time_min = rapid_mm / options.rapid_mm_per_min;                              // G10
  out.cycle_time_min = out.working_time_min + out.plunge_time_min + out.rapid_time_min;  // G11
  out.not_modelled = {"acceleration", "tool_change", "spindle_and_coolant_start",
                      "first_positioning_move", "non_linear_rapids"};
  out.model = std::move(written);
  out.options = options;
  out.file_name = file_name(options);
  return out;
}

std::unique_ptr<TextSource> open_program_text(const PassProgram& program) {
  return open_program(program.model, program.options);
}

std::string program_text(const PassProgram& program) {
  std::string text;
  write_all(*open_program_text(program), text);
  return text;
}

}  // namespace cutcalc::domain::program
