// Section 5 of spec polygon-holes.md: number format and program skeleton; P22 layers and ramps;
// P23 printed loop length and F words; the C words of the c_axis mode.

#include "domain/polygon/gcode_writer.h"

#include "domain/program/dialect_writer.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <numbers>
#include <string>
#include <string_view>
#include <utility>

#include "domain/common/interruption.h"
#include "domain/common/numeric.h"

namespace cutcalc::domain::polygon::detail {

namespace {

double parse(const std::string& text) {
  double value = 0.0;
  std::from_chars(text.data(), text.data() + text.size(), value);
  return value;
}

class Lines {
 public:
  void line(std::string_view text) {
    text_.append(text);
    text_.push_back('\n');
  }
  // Appends " {letter}{number}" (or "{letter}{number}" at the start of a line).
  Lines& word(char letter, std::string_view number) {
    if (!text_.empty() && text_.back() != '\n') {
      text_.push_back(' ');
    }
    text_.push_back(letter);
    text_.append(number);
    return *this;
  }
  void end_line() { text_.push_back('\n'); }
  void reserve(std::size_t size) { text_.reserve(size); }
  std::string take() { return std::move(text_); }

 private:
  std::string text_;
};

}  // namespace

std::string fmt4(double value) {
  std::array<char, 400> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                    std::chars_format::fixed, 4);
  std::string text(buffer.data(), result.ptr);
  if (text == "-0.0000") {
    text = "0.0000";
  }
  return text;
}

std::string NumberFormat::operator()(double mm) const {
  return program::format_fixed(mm * units_per_mm, decimals);
}

// P23
PrintedLoop print_loop(const std::vector<LoopBlock>& blocks, double scale,
                       const NumberFormat& fmt) {
  PrintedLoop loop;
  loop.blocks.reserve(blocks.size());
  Eigen::Vector2d S = scale * blocks.front().arc.start;  // unrounded start, (0, e) at a loop start
  loop.start_X = fmt(S.x());
  loop.start_Y = fmt(S.y());
  Eigen::Vector2d S_printed(parse(loop.start_X), parse(loop.start_Y));
  for (const LoopBlock& block : blocks) {
    const Eigen::Vector2d E = scale * block.arc.end;
    const Eigen::Vector2d C = scale * block.arc.centre;
    PrintedBlock printed{fmt(E.x()),         fmt(E.y()),  fmt(C.x() - S.x()),
                         fmt(C.y() - S.y()), block.t_end, scale * block.s_end};
    const Eigen::Vector2d E_printed(parse(printed.X), parse(printed.Y));
    const Eigen::Vector2d C_printed =
        S_printed + Eigen::Vector2d(parse(printed.I), parse(printed.J));
    const Eigen::Vector2d from = S_printed - C_printed;
    const Eigen::Vector2d to = E_printed - C_printed;
    double sweep = 2.0 * std::numbers::pi;  // E = S: a full circle
    if (E_printed != S_printed) {
      sweep = std::atan2(to.y(), to.x()) - std::atan2(from.y(), from.x());
      while (sweep <= 0.0) {
        sweep += 2.0 * std::numbers::pi;
      }
      while (sweep > 2.0 * std::numbers::pi) {
        sweep -= 2.0 * std::numbers::pi;
      }
    }
    loop.printed_length += sweep * 0.5 * (from.norm() + to.norm());
    loop.blocks.push_back(std::move(printed));
    S = E;
    S_printed = E_printed;
  }
  loop.printed_length /= fmt.units_per_mm;  // the printed numbers are in program units
  loop.fitted_length = scale * blocks.back().s_end;
  return loop;
}

// P22
Layers split_depth(double depth_mm, double step_down_mm) {
  Layers layers;
  layers.n = std::max(1.0, std::ceil(depth_mm / step_down_mm - 1e-9));
  layers.dz = depth_mm / layers.n;
  return layers;
}

double program_arc_blocks(double layers, int loops_per_layer, std::size_t blocks_per_loop) {
  const double loops = layers * loops_per_layer + (loops_per_layer == 1 ? 1.0 : 0.0);
  return loops * static_cast<double>(blocks_per_loop);
}

namespace {

// How the body is written: today's words and numbers, or a dialect's (programs.md section 2).
struct BodyStyle {
  NumberFormat fmt;
  const program::DialectWords* words = nullptr;
  std::string spindle_speed;                // the S word's number
  bool ramp_feed_along_projection = false;  // fanuc: F along the arc projected on XY
  program::Coolant coolant = program::Coolant::off;
};

// Section 5's body, P22, P23: from S M3 (c_axis: G0 X Y C0) through M5 (c_axis: the last G0 Z).
void write_body(Lines& out, const ProgramLayout& layout, const PrintedLoop& loop,
                const BodyStyle& style) {
  const program::DialectWords& words = *style.words;
  const NumberFormat& fmt = style.fmt;
  const bool c_axis = layout.synchronization == Synchronization::c_axis;
  const double L_p = loop.printed_length;
  const double L_u = loop.fitted_length;
  const std::string flat_F =
      fmt(c_axis ? layout.spindle_speed_rpm * layout.feed_per_rev_mm : layout.feed_per_rev_mm);
  const double ramp_ratio = layout.dz_mm / L_p;
  const std::string ramp_F =
      c_axis || style.ramp_feed_along_projection
          ? flat_F
          : fmt(layout.feed_per_rev_mm * std::sqrt(1.0 + ramp_ratio * ramp_ratio));
  const std::string safe_z = fmt(layout.safe_z_mm);
  const std::string zero = fmt(0.0);
  const int loops = layout.layers * layout.loops_per_layer + (layout.loops_per_layer == 1 ? 1 : 0);
  const double turn_per_loop = 2.0 * std::numbers::pi / (layout.N - 1.0);
  const auto coolant_on = [&] {
    if (style.coolant != program::Coolant::off) {
      out.line(style.coolant == program::Coolant::mist ? words.mist : words.flood);
    }
  };
  const auto coolant_off = [&] {
    if (style.coolant != program::Coolant::off) out.line(words.coolant_off);
  };
  const std::string_view rapid = words.rapid + 1;  // the number after the letter
  const std::string_view feed = words.feed + 1;
  const std::string_view arc = words.arc_ccw + 1;

  if (c_axis) {
    coolant_on();
    out.word('G', rapid).word('X', loop.start_X).word('Y', loop.start_Y).word('C', zero).end_line();
    out.word('G', "94").word('F', flat_F).end_line();
  } else {
    out.word('S', style.spindle_speed).word('M', words.spindle_on + 1).end_line();
    coolant_on();
    out.word('G', rapid).word('X', loop.start_X).word('Y', loop.start_Y).end_line();
    out.word('G', "95").word('F', ramp_F).end_line();
  }
  out.word('G', feed).word('Z', zero).end_line();

  bool previous_ramp = true;
  for (int loop_index = 0; loop_index < loops; ++loop_index) {
    interruption_point();
    // P22: layer k = loop_index / loops_per_layer + 1; its first loop ramps.
    const int layer = std::min(loop_index / layout.loops_per_layer + 1, layout.layers);
    const bool ramp = loop_index < layout.layers * layout.loops_per_layer &&
                      loop_index % layout.loops_per_layer == 0;
    const double z_top = -(layer - 1) * layout.dz_mm;
    const double z_bottom = -layer * layout.dz_mm;
    // P23: an F line before every ramp loop and whenever the kind of loop changes (G95 only:
    // the c_axis F is the same for every loop).
    if (!c_axis && loop_index > 0 && (ramp || ramp != previous_ramp)) {
      out.word('G', "95").word('F', ramp ? ramp_F : flat_F).end_line();
    }
    previous_ramp = ramp;
    const double t_loop = loop_index * turn_per_loop;
    for (std::size_t b = 0; b < loop.blocks.size(); ++b) {
      const PrintedBlock& block = loop.blocks[b];
      out.word('G', arc).word('X', block.X).word('Y', block.Y);
      if (ramp) {
        const bool last = b + 1 == loop.blocks.size();
        out.word('Z', fmt(last ? z_bottom : z_top - layout.dz_mm * block.s_end / L_u));
      }
      out.word('I', block.I).word('J', block.J);
      if (c_axis) {
        // Degrees, in every unit system.
        out.word('C', program::format_fixed(-rad_to_deg(t_loop + block.t_end), fmt.decimals));
      }
      out.end_line();
    }
  }

  out.word('G', rapid).word('Z', safe_z).end_line();
  if (!c_axis) {
    out.line("G94");
    out.line(words.spindle_off);
  }
  coolant_off();
}

std::size_t body_size(const ProgramLayout& layout, const PrintedLoop& loop) {
  const bool c_axis = layout.synchronization == Synchronization::c_axis;
  const int loops = layout.layers * layout.loops_per_layer + (layout.loops_per_layer == 1 ? 1 : 0);
  return static_cast<std::size_t>(loops) * loop.blocks.size() * (c_axis ? 64 : 48) + 2048;
}

}  // namespace

std::vector<std::string> program_comments(const ProgramLayout& layout, const PrintedLoop& loop,
                                          bool ramp_feed_along_projection) {
  const bool c_axis = layout.synchronization == Synchronization::c_axis;
  const double L_p = loop.printed_length;
  const std::string flat_F =
      fmt4(c_axis ? layout.spindle_speed_rpm * layout.feed_per_rev_mm : layout.feed_per_rev_mm);
  const double ramp_ratio = layout.dz_mm / L_p;
  const std::string ramp_F =
      c_axis ? flat_F : fmt4(layout.feed_per_rev_mm * std::sqrt(1.0 + ramp_ratio * ramp_ratio));
  std::vector<std::string> comments = {
      "CUTCALC POLYGON HOLE N" + std::to_string(layout.N) + " D" + fmt4(layout.d_mm) + " A" +
          fmt4(layout.a_mm),
      "ROTOR " + std::to_string(layout.N - 1) + " CORNERS ON DIAMETER " + fmt4(2.0 * layout.r_mm) +
          " ECCENTRICITY " + fmt4(layout.e_mm),
      "LOOP LENGTH " + fmt4(L_p) + " EXACT " + fmt4(layout.exact_loop_length_mm) +
          " BLOCKS PER LOOP " + std::to_string(loop.blocks.size()) + " TOLERANCE " +
          fmt4(layout.tolerance_mm) + " DEVIATION " + fmt4(layout.deviation_mm),
      "DEPTH " + fmt4(layout.depth_mm) + " IN " + std::to_string(layout.layers) + " LAYERS OF " +
          fmt4(layout.dz_mm) + " STEP DOWN " + fmt4(layout.step_down_mm) + " LOOPS PER LAYER " +
          std::to_string(layout.loops_per_layer) + " FIRST LOOP OF A LAYER A HELICAL RAMP"};
  if (c_axis) {
    comments.push_back("SPINDLE AS ROTARY AXIS C IN POSITION MODE: C0 = CORNER 0 POINTING -Y");
    comments.push_back("C = MINUS ROTOR TURN IN DEGREES CUMULATIVE. G94 F " + flat_F +
                       " MM PER MIN");
  } else {
    comments.push_back("G95 FEED PER SPINDLE REV " + flat_F + " AT " +
                       fmt4(layout.spindle_speed_rpm) + " RPM. RAMP LOOPS " +
                       (ramp_feed_along_projection ? flat_F + " ALONG THE ARC PROJECTION (HTG = 0)"
                                                   : ramp_F + " ALONG THE HELIX"));
  }
  comments.push_back("FRAME: HOLE CENTRE X0 Y0 TOP FACE Z0 SIDE 0 AT Y-" + fmt4(0.5 * layout.d_mm) +
                     " PATH G3 CCW ROTOR CW. " + std::to_string(layout.N - 1) +
                     " LOOPS PER SPINDLE REV");
  return comments;
}

// Section 5, P22, P23
std::string write_program(const ProgramLayout& layout, const PrintedLoop& loop) {
  Lines out;
  out.reserve(body_size(layout, loop));
  out.line("%");
  for (const std::string& comment : program_comments(layout, loop)) {
    out.line("(" + comment + ")");
  }
  out.line("G21 G17 G90 G40 G80 G94");
  out.word('G', "0").word('Z', fmt4(layout.safe_z_mm)).end_line();
  BodyStyle style;
  style.words = &program::words_of(program::Dialect::linuxcnc);
  style.spindle_speed = fmt4(layout.spindle_speed_rpm);
  write_body(out, layout, loop, style);
  out.line("M30");
  out.line("%");
  return out.take();
}

std::string write_dialect_program(const ProgramLayout& layout, const PrintedLoop& loop,
                                  const std::vector<std::string>& comments,
                                  const program::ProgramOptions& options) {
  const int decimals = program::decimals_of(options);
  BodyStyle style;
  style.fmt = {decimals, options.units == program::Units::inch ? 1.0 / program::kMmPerInch : 1.0};
  style.words = &program::words_of(options.dialect);
  style.spindle_speed = program::spindle_text(layout.spindle_speed_rpm, options.dialect, decimals);
  style.ramp_feed_along_projection = options.dialect == program::Dialect::fanuc;
  style.coolant = options.coolant;
  Lines body;
  body.reserve(body_size(layout, loop));
  write_body(body, layout, loop, style);
  return program::program_header(comments, options) +
         program::safe_start_text(
             {options.tool_number, options.tool_length_offset, layout.safe_z_mm}, options) +
         body.take() + program::program_end(options);
}

}  // namespace cutcalc::domain::polygon::detail
