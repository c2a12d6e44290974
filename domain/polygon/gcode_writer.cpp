// Section 5 of spec polygon-holes.md: number format and program skeleton; P22 layers and ramps;
// P23 printed loop length and F words; the C words of the c_axis mode.

#include "domain/polygon/gcode_writer.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <numbers>
#include <string>
#include <string_view>
#include <utility>

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

// P23
PrintedLoop print_loop(const std::vector<LoopBlock>& blocks, double scale) {
  PrintedLoop loop;
  loop.blocks.reserve(blocks.size());
  Eigen::Vector2d S = scale * blocks.front().arc.start;  // unrounded start, (0, e) at a loop start
  loop.start_X = fmt4(S.x());
  loop.start_Y = fmt4(S.y());
  Eigen::Vector2d S_printed(parse(loop.start_X), parse(loop.start_Y));
  for (const LoopBlock& block : blocks) {
    const Eigen::Vector2d E = scale * block.arc.end;
    const Eigen::Vector2d C = scale * block.arc.centre;
    PrintedBlock printed{fmt4(E.x()),         fmt4(E.y()), fmt4(C.x() - S.x()),
                         fmt4(C.y() - S.y()), block.t_end, scale * block.s_end};
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

// Section 5, P22, P23
std::string write_program(const ProgramLayout& layout, const PrintedLoop& loop) {
  const bool c_axis = layout.synchronization == Synchronization::c_axis;
  const double L_p = loop.printed_length;
  const double L_u = loop.fitted_length;
  const std::string flat_F =
      fmt4(c_axis ? layout.spindle_speed_rpm * layout.feed_per_rev_mm : layout.feed_per_rev_mm);
  const double ramp_ratio = layout.dz_mm / L_p;
  const std::string ramp_F =
      c_axis ? flat_F : fmt4(layout.feed_per_rev_mm * std::sqrt(1.0 + ramp_ratio * ramp_ratio));
  const std::string safe_z = fmt4(layout.safe_z_mm);
  const int loops = layout.layers * layout.loops_per_layer + (layout.loops_per_layer == 1 ? 1 : 0);
  const double turn_per_loop = 2.0 * std::numbers::pi / (layout.N - 1.0);

  Lines out;
  out.reserve(static_cast<std::size_t>(loops) * loop.blocks.size() * (c_axis ? 64 : 48) + 2048);
  out.line("%");
  out.line("(CUTCALC POLYGON HOLE N" + std::to_string(layout.N) + " D" + fmt4(layout.d_mm) + " A" +
           fmt4(layout.a_mm) + ")");
  out.line("(ROTOR " + std::to_string(layout.N - 1) + " CORNERS ON DIAMETER " +
           fmt4(2.0 * layout.r_mm) + " ECCENTRICITY " + fmt4(layout.e_mm) + ")");
  out.line("(LOOP LENGTH " + fmt4(L_p) + " EXACT " + fmt4(layout.exact_loop_length_mm) +
           " BLOCKS PER LOOP " + std::to_string(loop.blocks.size()) + " TOLERANCE " +
           fmt4(layout.tolerance_mm) + " DEVIATION " + fmt4(layout.deviation_mm) + ")");
  out.line("(DEPTH " + fmt4(layout.depth_mm) + " IN " + std::to_string(layout.layers) +
           " LAYERS OF " + fmt4(layout.dz_mm) + " STEP DOWN " + fmt4(layout.step_down_mm) +
           " LOOPS PER LAYER " + std::to_string(layout.loops_per_layer) +
           " FIRST LOOP OF A LAYER A HELICAL RAMP)");
  if (c_axis) {
    out.line("(SPINDLE AS ROTARY AXIS C IN POSITION MODE: C0 = CORNER 0 POINTING -Y)");
    out.line("(C = MINUS ROTOR TURN IN DEGREES CUMULATIVE. G94 F " + flat_F + " MM PER MIN)");
  } else {
    out.line("(G95 FEED PER SPINDLE REV " + flat_F + " AT " + fmt4(layout.spindle_speed_rpm) +
             " RPM. RAMP LOOPS " + ramp_F + " ALONG THE HELIX)");
  }
  out.line("(FRAME: HOLE CENTRE X0 Y0 TOP FACE Z0 SIDE 0 AT Y-" + fmt4(0.5 * layout.d_mm) +
           " PATH G3 CCW ROTOR CW. " + std::to_string(layout.N - 1) + " LOOPS PER SPINDLE REV)");
  out.line("G21 G17 G90 G40 G80 G94");
  out.word('G', "0").word('Z', safe_z).end_line();
  if (c_axis) {
    out.word('G', "0")
        .word('X', loop.start_X)
        .word('Y', loop.start_Y)
        .word('C', "0.0000")
        .end_line();
    out.word('G', "94").word('F', flat_F).end_line();
  } else {
    out.word('S', fmt4(layout.spindle_speed_rpm)).word('M', "3").end_line();
    out.word('G', "0").word('X', loop.start_X).word('Y', loop.start_Y).end_line();
    out.word('G', "95").word('F', ramp_F).end_line();
  }
  out.line("G1 Z0.0000");

  bool previous_ramp = true;
  for (int loop_index = 0; loop_index < loops; ++loop_index) {
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
      out.word('G', "3").word('X', block.X).word('Y', block.Y);
      if (ramp) {
        const bool last = b + 1 == loop.blocks.size();
        out.word('Z', fmt4(last ? z_bottom : z_top - layout.dz_mm * block.s_end / L_u));
      }
      out.word('I', block.I).word('J', block.J);
      if (c_axis) {
        out.word('C', fmt4(-(180.0 / std::numbers::pi) * (t_loop + block.t_end)));
      }
      out.end_line();
    }
  }

  out.word('G', "0").word('Z', safe_z).end_line();
  if (!c_axis) {
    out.line("G94");
    out.line("M5");
  }
  out.line("M30");
  out.line("%");
  return out.take();
}

}  // namespace cutcalc::domain::polygon::detail
