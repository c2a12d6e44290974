// generate_polygon_hole: spec polygon-holes.md P1-P34 put together (paper 004, corrected).
// The fit runs on the unit-diameter hole (d = 1) and is scaled to mm for the output, so that no
// diameter overflows the squares of P19.

#include "domain/polygon/polygon_hole.h"

#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include "domain/polygon/biarc_fit.h"
#include "domain/polygon/block_rate.h"
#include "domain/polygon/centre_path.h"
#include "domain/polygon/gcode_writer.h"
#include "domain/polygon/hole_prediction.h"
#include "domain/polygon/machining_time.h"
#include "domain/polygon/polygon_geometry.h"
#include "domain/polygon/printed_deviation.h"
#include "domain/polygon/rotor.h"
#include "domain/polygon/rotor_dimensions.h"
#include "domain/program/dialect_writer.h"
#include "domain/program/program_size.h"

namespace cutcalc::domain::polygon {

namespace {

constexpr double kMergeTolerance = 1e-9;  // P21, times d (= 1 here)

// A comment must not hold parentheses, commas, % or non-ASCII characters (section 5).
std::string comment_safe(const std::string& text) {
  std::string safe;
  safe.reserve(text.size());
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '(' || c == ')' || c == ',' || c == '%' || byte < 0x20 || byte > 0x7e) {
      safe.push_back(' ');
    } else {
      safe.push_back(c);
    }
  }
  return safe;
}

}  // namespace

Result<PolygonHoleResult> generate_polygon_hole(const PolygonHoleParams& params) {
  const int N = params.faces;
  const double d = params.inscribed_diameter_mm;
  const detail::PolygonShape shape_mm = detail::make_polygon_shape(N, d);  // P1-P5 in mm
  const detail::PolygonShape unit_shape = detail::make_polygon_shape(N, 1.0);
  const detail::CentrePath path(unit_shape);  // P6-P10
  const detail::Rotor rotor(unit_shape);      // P11-P13

  // P18-P21
  auto fit = detail::fit_ellipse_arc(path, params.tolerance_mm / d, kMaxBiarcsPerEllipseArc);
  if (!fit.ok()) {
    return fit.error();
  }
  const std::vector<detail::LoopBlock> blocks =
      detail::loop_blocks(path, fit.value(), kMergeTolerance);
  for (const detail::LoopBlock& block : blocks) {
    if (!(block.arc.sweep > 0.0) || !std::isfinite(block.arc.radius)) {
      return make_error(ErrorCode::not_converged,
                        "the arc fit produced a block that is not a counter-clockwise arc");
    }
  }

  // P22 and the section 10 size limit.
  const int loops_per_layer = params.loops_per_layer.value_or(N - 1);
  const detail::Layers layers = detail::split_depth(params.depth_mm, params.step_down_mm);
  if (!(detail::program_arc_blocks(layers.n, loops_per_layer, blocks.size()) <=
        program::kMaxProgramBlocks)) {
    return make_limit_error(ErrorCode::program_too_large, program::kMaxProgramBlocks);
  }

  // P23, in the program's units and decimals when a `program` object is given.
  detail::NumberFormat format;
  if (params.program) {
    format.decimals = program::decimals_of(*params.program);
    format.units_per_mm =
        params.program->units == program::Units::inch ? 1.0 / program::kMmPerInch : 1.0;
  }
  const detail::PrintedLoop loop = detail::print_loop(blocks, d, format);

  PolygonHoleResult result;
  result.blocks_per_loop = static_cast<int>(blocks.size());
  result.loop_length_mm = loop.printed_length;
  result.feed_per_rev_mm = (N - 1) * loop.printed_length;
  result.eccentricity_mm = shape_mm.e;
  result.max_path_deviation_mm = fit.value().deviation * d;
  // P24, P25 (P26 on demand: predicted_overcut_mm)
  result.overcut = std::make_shared<const detail::OvercutPrediction>(detail::OvercutPrediction{
      unit_shape, rotor,
      detail::motion_segments(unit_shape, fit.value(), blocks, params.synchronization), d});
  // P15, P17
  result.uncut_corner_area_mm2 = detail::uncut_area_coefficient(N) * d * d;
  result.corner_gap_mm = detail::corner_gap(shape_mm);
  // P27
  result.max_feed_by_block_rate_mm_per_min = detail::max_feed_by_block_rate(
      detail::shortest_block_length(blocks) * d, params.block_time_ms);
  // P28-P31
  result.rotor = detail::rotor_dimensions(shape_mm);
  result.corner_radius_mm = detail::corner_wall_min_radius(path) * d;
  // P32-P34, from the unrounded L_p
  result.time = detail::machining_time(
      {.N = N,
       .layers = layers.n,
       .dz_mm = layers.dz,
       .loops_per_layer = loops_per_layer,
       .spindle_speed_rpm = params.spindle_speed_rpm,
       .loop_length_mm = result.loop_length_mm,
       .feed_per_rev_mm = result.feed_per_rev_mm,
       .safe_z_mm = params.safe_z_mm,
       .depth_mm = params.depth_mm,
       .rapid_mm_per_min = params.rapid_mm_per_min,
       .synchronization = params.synchronization,
       .plunge_at_ramp_feed =
           !(params.program && params.program->dialect == program::Dialect::fanuc)});
  result.warnings = detail::program_warnings(params.synchronization,
                                             params.spindle_speed_rpm * result.feed_per_rev_mm,
                                             result.max_feed_by_block_rate_mm_per_min);

  detail::ProgramLayout layout;
  layout.N = N;
  layout.d_mm = d;
  layout.a_mm = shape_mm.a;
  layout.r_mm = shape_mm.r;
  layout.e_mm = shape_mm.e;
  layout.exact_loop_length_mm = path.loop_length() * d;
  layout.tolerance_mm = params.tolerance_mm;
  layout.deviation_mm = result.max_path_deviation_mm;
  layout.depth_mm = params.depth_mm;
  layout.step_down_mm = params.step_down_mm;
  layout.layers = static_cast<int>(layers.n);
  layout.dz_mm = layers.dz;
  layout.loops_per_layer = loops_per_layer;
  layout.safe_z_mm = params.safe_z_mm;
  layout.spindle_speed_rpm = params.spindle_speed_rpm;
  layout.synchronization = params.synchronization;
  layout.feed_per_rev_mm = result.feed_per_rev_mm;
  // programs.md 1.2: an S or F word that prints as 0 would stop a G95 program (no feed) or the
  // spindle; refused as the pass program refuses it.
  {
    const int decimals = params.program ? program::decimals_of(*params.program) : 4;
    const double per_mm = params.program && params.program->units == program::Units::inch
                              ? 1.0 / program::kMmPerInch
                              : 1.0;
    const double feed = params.synchronization == Synchronization::c_axis
                            ? params.spindle_speed_rpm * result.feed_per_rev_mm
                            : result.feed_per_rev_mm;
    const std::string s_word =
        params.program
            ? program::spindle_text(params.spindle_speed_rpm, params.program->dialect, decimals)
            : program::format_fixed(params.spindle_speed_rpm, detail::kPlainDecimals);
    if (program::prints_as_zero(s_word) ||
        program::prints_as_zero(program::format_fixed(feed * per_mm, decimals))) {
      return make_error(ErrorCode::word_prints_as_zero, "S or F");
    }
  }
  if (!params.program) {
    result.program = detail::plain_program(layout, loop);
    result.file_name = "polygon-hole-N" + std::to_string(N) + "-d" +
                       program::format_fixed(d, detail::kPlainDecimals) + ".ngc";
    return result;
  }
  const program::ProgramOptions& options = *params.program;
  result.printed_path_deviation_mm =
      detail::printed_path_deviation_mm(path, d, blocks, loop, 1.0 / format.units_per_mm);
  // programs.md section 5: the limits, the Fanuc S word, the printed deviation, then today's.
  const double flat_feed = params.spindle_speed_rpm * result.feed_per_rev_mm;
  const double ramp_ratio = layout.dz_mm / result.loop_length_mm;
  const bool ramp_along_helix = params.synchronization == Synchronization::feed_per_rev &&
                                options.dialect != program::Dialect::fanuc;
  std::vector<program::Warning> warnings = program::limit_warnings(
      params.spindle_speed_rpm,
      {flat_feed,
       ramp_along_helix ? flat_feed * std::sqrt(1.0 + ramp_ratio * ramp_ratio) : flat_feed},
      params.machine);
  if (options.dialect == program::Dialect::fanuc &&
      params.synchronization == Synchronization::feed_per_rev &&
      program::fanuc_s_rounds(params.spindle_speed_rpm)) {
    warnings.push_back({program::WarningCode::spindle_speed_rounded,
                        "a Fanuc S word takes no decimals: the spindle speed is printed rounded "
                        "half up (the feed per revolution is exact)"});
  }
  if (*result.printed_path_deviation_mm > params.tolerance_mm) {
    warnings.push_back(
        {program::WarningCode::rounding_exceeds_tolerance,
         "the program as printed deviates " +
             program::format_fixed(*result.printed_path_deviation_mm, detail::kPlainDecimals) +
             " mm from the exact path, more than tolerance_mm: print more decimals"});
  }
  warnings.insert(warnings.end(), result.warnings.begin(), result.warnings.end());
  result.warnings = std::move(warnings);

  std::vector<std::string> comments =
      detail::program_comments(layout, loop, options.dialect == program::Dialect::fanuc);
  std::vector<std::string> warning_lines;
  for (const program::Warning& warning : result.warnings) {
    warning_lines.push_back(program::comment_text(warning));
  }
  comments.insert(comments.begin() + 1, warning_lines.begin(), warning_lines.end());
  if (params.synchronization == Synchronization::c_axis &&
      options.dialect != program::Dialect::linuxcnc) {
    comments.push_back(
        "SWITCH THE SPINDLE TO ITS C AXIS POSITION MODE BEFORE THIS PROGRAM AND BACK AFTER IT: "
        "A MACHINE-SPECIFIC COMMAND, NOT WRITTEN HERE");
  }
  if (options.units == program::Units::inch) {
    // The comment numbers stay in mm (4 decimals of an inch would print the tolerance as 0).
    comments.push_back("NUMBERS IN THESE COMMENTS IN MM, PROGRAM UNITS INCH");
  }
  result.program = detail::dialect_program(layout, loop, comments, options);
  result.file_name = program::file_name(options);
  return result;
}

// P26
double predicted_overcut_mm(const PolygonHoleResult& result) {
  const detail::OvercutPrediction& overcut = *result.overcut;
  return detail::predicted_overcut(overcut.unit_shape, overcut.rotor, overcut.segments) *
         overcut.d_mm;
}

std::unique_ptr<TextSource> open_program_text(const PolygonHoleResult& result,
                                              bool warning_comments) {
  std::string head = result.program->head;
  // A dialect program has its warning lines already.
  if (warning_comments && !result.printed_path_deviation_mm && !result.warnings.empty()) {
    // After the first comment line: the line after the leading "%".
    const std::size_t first_line_end = head.find('\n');
    const std::size_t comment_end =
        first_line_end == std::string::npos ? first_line_end : head.find('\n', first_line_end + 1);
    if (comment_end != std::string::npos) {
      std::string comments;
      for (const program::Warning& warning : result.warnings) {
        // Appended piece by piece: GCC 12's -Wrestrict misfires on "literal" + std::string.
        comments.append("(").append(comment_safe(program::comment_text(warning))).append(")\n");
      }
      head.insert(comment_end + 1, comments);
    }
  }
  return detail::open_program(result.program, std::move(head));
}

std::string program_text(const PolygonHoleResult& result, bool warning_comments) {
  std::string text;
  write_all(*open_program_text(result, warning_comments), text);
  return text;
}

}  // namespace cutcalc::domain::polygon
