// Section 5 of spec polygon-holes.md: number format and program skeleton; P22 layers and ramps;
// P23 printed loop length and F words; the C words of the c_axis mode.

#include "domain/polygon/gcode_writer.h"

#include "domain/program/dialect_writer.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <memory>
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

}  // namespace

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
  layers.n = ceil_count(depth_mm / step_down_mm);
  layers.dz = depth_mm / layers.n;
  return layers;
}

double program_arc_blocks(double layers, int loops_per_layer, std::size_t blocks_per_loop) {
  const double loops = layers * loops_per_layer + (loops_per_layer == 1 ? 1.0 : 0.0);
  return loops * static_cast<double>(blocks_per_loop);
}

namespace {

// Appends words and lines to a text.
class Lines {
 public:
  explicit Lines(std::string& text) : text_(text) {}
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
  void raw(std::string_view text) { text_.append(text); }
  [[nodiscard]] std::size_t size() const { return text_.size(); }

 private:
  std::string& text_;
};

// Section 5's body, P22, P23, written as it is read: from S M3 (c_axis: G0 X Y C0) through M5
// (c_axis: the last G0 Z), then the program's end. Holds the printed loop and where it is.
class BodyWriter final : public TextSource {
 public:
  BodyWriter(std::shared_ptr<const PolygonProgram> program, std::string head)
      : program_(std::move(program)),
        program_bytes_(program_->held_bytes()),
        head_(std::move(head)) {
    const ProgramLayout& layout = program_->layout;
    const NumberFormat& fmt = program_->style.fmt;
    c_axis_ = layout.synchronization == Synchronization::c_axis;
    flat_F_ =
        fmt(c_axis_ ? layout.spindle_speed_rpm * layout.feed_per_rev_mm : layout.feed_per_rev_mm);
    const double ramp_ratio = layout.dz_mm / program_->loop.printed_length;
    ramp_F_ = c_axis_ || program_->style.ramp_feed_along_projection
                  ? flat_F_
                  : fmt(layout.feed_per_rev_mm * std::sqrt(1.0 + ramp_ratio * ramp_ratio));
    loops_ = layout.layers * layout.loops_per_layer + (layout.loops_per_layer == 1 ? 1 : 0);
  }

  bool write_next(std::string& text, std::size_t max_bytes) override {
    Lines out(text);
    const std::size_t until = text.size() + max_bytes;
    switch (part_) {
      case Part::head:
        out.raw(head_);
        write_start(out);
        part_ = Part::loops;
        if (text.size() >= until) return true;
        [[fallthrough]];
      case Part::loops:
        if (!write_loops(out, until)) return true;
        write_end(out);
        part_ = Part::done;
        return false;
      case Part::done:
        break;
    }
    return false;
  }

  [[nodiscard]] std::size_t held_bytes() const override {
    return sizeof(*this) + head_.capacity() + program_bytes_;
  }

 private:
  enum class Part { head, loops, done };

  void write_start(Lines& out) const {
    const PrintedLoop& loop = program_->loop;
    const program::DialectWords& words = *program_->style.words;
    const std::string_view rapid = words.rapid + 1;  // the number after the letter
    const std::string_view feed = words.feed + 1;
    const std::string zero = program_->style.fmt(0.0);
    if (c_axis_) {
      coolant_on(out);
      out.word('G', rapid)
          .word('X', loop.start_X)
          .word('Y', loop.start_Y)
          .word('C', zero)
          .end_line();
      out.word('G', "94").word('F', flat_F_).end_line();
    } else {
      out.word('S', program_->style.spindle_speed).word('M', words.spindle_on + 1).end_line();
      coolant_on(out);
      out.word('G', rapid).word('X', loop.start_X).word('Y', loop.start_Y).end_line();
      out.word('G', "95").word('F', ramp_F_).end_line();
    }
    out.word('G', feed).word('Z', zero).end_line();
  }

  // Writes blocks until `until` bytes; true once the last loop is written.
  bool write_loops(Lines& out, std::size_t until) {
    const ProgramLayout& layout = program_->layout;
    const PrintedLoop& loop = program_->loop;
    const NumberFormat& fmt = program_->style.fmt;
    const std::string_view arc = program_->style.words->arc_ccw + 1;
    const double L_u = loop.fitted_length;
    const double turn_per_loop = 2.0 * std::numbers::pi / (layout.N - 1.0);
    for (; loop_index_ < loops_; ++loop_index_, block_ = 0) {
      interruption_point();
      // P22: layer k = loop_index / loops_per_layer + 1; its first loop ramps.
      const int layer = std::min(loop_index_ / layout.loops_per_layer + 1, layout.layers);
      const bool ramp = loop_index_ < layout.layers * layout.loops_per_layer &&
                        loop_index_ % layout.loops_per_layer == 0;
      const double z_top = -(layer - 1) * layout.dz_mm;
      const double z_bottom = -layer * layout.dz_mm;
      // P23: an F line before every ramp loop and whenever the kind of loop changes (G95 only:
      // the c_axis F is the same for every loop).
      if (block_ == 0) {
        if (!c_axis_ && loop_index_ > 0 && (ramp || ramp != previous_ramp_)) {
          out.word('G', "95").word('F', ramp ? ramp_F_ : flat_F_).end_line();
        }
        previous_ramp_ = ramp;
      }
      const double t_loop = loop_index_ * turn_per_loop;
      for (; block_ < loop.blocks.size(); ++block_) {
        if (out.size() >= until) return false;
        const PrintedBlock& block = loop.blocks[block_];
        out.word('G', arc).word('X', block.X).word('Y', block.Y);
        if (ramp) {
          const bool last = block_ + 1 == loop.blocks.size();
          out.word('Z', fmt(last ? z_bottom : z_top - layout.dz_mm * block.s_end / L_u));
        }
        out.word('I', block.I).word('J', block.J);
        if (c_axis_) {
          // Degrees, in every unit system.
          out.word('C', program::format_fixed(-rad_to_deg(t_loop + block.t_end), fmt.decimals));
        }
        out.end_line();
      }
    }
    return true;
  }

  void write_end(Lines& out) const {
    const program::DialectWords& words = *program_->style.words;
    out.word('G', words.rapid + 1).word('Z', program_->style.fmt(program_->layout.safe_z_mm));
    out.end_line();
    if (!c_axis_) {
      out.line("G94");
      out.line(words.spindle_off);
    }
    if (program_->style.coolant != program::Coolant::off) out.line(words.coolant_off);
    out.raw(program_->tail);
  }

  void coolant_on(Lines& out) const {
    const BodyStyle& style = program_->style;
    if (style.coolant != program::Coolant::off) {
      out.line(style.coolant == program::Coolant::mist ? style.words->mist : style.words->flood);
    }
  }

  std::shared_ptr<const PolygonProgram> program_;
  std::size_t program_bytes_;  // the program is immutable: counted once, asked for every piece
  std::string head_;
  bool c_axis_ = false;
  std::string flat_F_;
  std::string ramp_F_;
  int loops_ = 0;
  Part part_ = Part::head;
  int loop_index_ = 0;
  std::size_t block_ = 0;
  bool previous_ramp_ = true;
};

}  // namespace

std::size_t PolygonProgram::held_bytes() const {
  std::size_t bytes = sizeof(*this) + head.capacity() + tail.capacity() +
                      loop.blocks.capacity() * sizeof(PrintedBlock);
  for (const PrintedBlock& block : loop.blocks) {
    // Numbers longer than the small-string buffer live on the heap.
    for (const std::string* word : {&block.X, &block.Y, &block.I, &block.J}) {
      if (word->size() >= sizeof(std::string)) bytes += word->capacity() + 1;
    }
  }
  return bytes;
}

std::unique_ptr<TextSource> open_program(std::shared_ptr<const PolygonProgram> program,
                                         std::string head) {
  return std::make_unique<BodyWriter>(std::move(program), std::move(head));
}

std::vector<std::string> program_comments(const ProgramLayout& layout, const PrintedLoop& loop,
                                          bool ramp_feed_along_projection) {
  const auto plain = [](double value) { return program::format_fixed(value, kPlainDecimals); };
  const bool c_axis = layout.synchronization == Synchronization::c_axis;
  const double L_p = loop.printed_length;
  const std::string flat_F =
      plain(c_axis ? layout.spindle_speed_rpm * layout.feed_per_rev_mm : layout.feed_per_rev_mm);
  const double ramp_ratio = layout.dz_mm / L_p;
  const std::string ramp_F =
      c_axis ? flat_F : plain(layout.feed_per_rev_mm * std::sqrt(1.0 + ramp_ratio * ramp_ratio));
  std::vector<std::string> comments = {
      "CUTCALC POLYGON HOLE N" + std::to_string(layout.N) + " D" + plain(layout.d_mm) + " A" +
          plain(layout.a_mm),
      "ROTOR " + std::to_string(layout.N - 1) + " CORNERS ON DIAMETER " + plain(2.0 * layout.r_mm) +
          " ECCENTRICITY " + plain(layout.e_mm),
      "LOOP LENGTH " + plain(L_p) + " EXACT " + plain(layout.exact_loop_length_mm) +
          " BLOCKS PER LOOP " + std::to_string(loop.blocks.size()) + " TOLERANCE " +
          plain(layout.tolerance_mm) + " DEVIATION " + plain(layout.deviation_mm),
      "DEPTH " + plain(layout.depth_mm) + " IN " + std::to_string(layout.layers) + " LAYERS OF " +
          plain(layout.dz_mm) + " STEP DOWN " + plain(layout.step_down_mm) + " LOOPS PER LAYER " +
          std::to_string(layout.loops_per_layer) + " FIRST LOOP OF A LAYER A HELICAL RAMP"};
  if (c_axis) {
    comments.push_back("SPINDLE AS ROTARY AXIS C IN POSITION MODE: C0 = CORNER 0 POINTING -Y");
    comments.push_back("C = MINUS ROTOR TURN IN DEGREES CUMULATIVE. G94 F " + flat_F +
                       " MM PER MIN");
  } else {
    comments.push_back("G95 FEED PER SPINDLE REV " + flat_F + " AT " +
                       plain(layout.spindle_speed_rpm) + " RPM. RAMP LOOPS " +
                       (ramp_feed_along_projection ? flat_F + " ALONG THE ARC PROJECTION (HTG = 0)"
                                                   : ramp_F + " ALONG THE HELIX"));
  }
  comments.push_back("FRAME: HOLE CENTRE X0 Y0 TOP FACE Z0 SIDE 0 AT Y-" +
                     plain(0.5 * layout.d_mm) + " PATH G3 CCW ROTOR CW. " +
                     std::to_string(layout.N - 1) + " LOOPS PER SPINDLE REV");
  return comments;
}

// Section 5, P22, P23
std::shared_ptr<const PolygonProgram> plain_program(const ProgramLayout& layout,
                                                    const PrintedLoop& loop) {
  auto program = std::make_shared<PolygonProgram>();
  Lines out(program->head);
  out.line("%");
  for (const std::string& comment : program_comments(layout, loop)) {
    out.line("(" + comment + ")");
  }
  out.line("G21 G17 G90 G40 G80 G94");
  out.word('G', "0").word('Z', program::format_fixed(layout.safe_z_mm, kPlainDecimals)).end_line();
  program->layout = layout;
  program->loop = loop;
  program->style.words = &program::words_of(program::Dialect::linuxcnc);
  program->style.spindle_speed = program::format_fixed(layout.spindle_speed_rpm, kPlainDecimals);
  program->tail = "M30\n%\n";
  return program;
}

std::shared_ptr<const PolygonProgram> dialect_program(const ProgramLayout& layout,
                                                      const PrintedLoop& loop,
                                                      const std::vector<std::string>& comments,
                                                      const program::ProgramOptions& options) {
  auto program = std::make_shared<PolygonProgram>();
  const int decimals = program::decimals_of(options);
  program->head = program::program_header(comments, options) +
                  program::safe_start_text(
                      {options.tool_number, options.tool_length_offset, layout.safe_z_mm}, options);
  program->layout = layout;
  program->loop = loop;
  BodyStyle& style = program->style;
  style.fmt = {decimals, options.units == program::Units::inch ? 1.0 / program::kMmPerInch : 1.0};
  style.words = &program::words_of(options.dialect);
  style.spindle_speed = program::spindle_text(layout.spindle_speed_rpm, options.dialect, decimals);
  style.ramp_feed_along_projection = options.dialect == program::Dialect::fanuc;
  style.coolant = options.coolant;
  program->tail = program::program_end(options);
  return program;
}

}  // namespace cutcalc::domain::polygon::detail
