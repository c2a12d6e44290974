// Spec machine-time.md section 4 (dialects) and section 7 (path control words); the programs
// cutcalc writes: programs.md section 3, grooving-cycle.md 5.2, lathe-flat.md 6.4.
//
// Each block runs in rs274ngc's order of execution, which Fanuc and Sinumerik share where it
// matters: modes first (feed mode, units, plane, distance, diameter, path), then F and S, the tool
// change, the spindle, a dwell, the motion, and last the stops and the program end.

#include "domain/machine_time/gcode_reader.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <variant>

#include "domain/common/interruption.h"
#include "domain/machine_time/gcode_arc.h"
#include "domain/machine_time/gcode_codes.h"
#include "domain/machine_time/gcode_lexer.h"

namespace cutcalc::domain::machine_time {
namespace {

using detail::Block;
using detail::CodeWord;
using detail::DiameterWord;
using detail::GAction;
using detail::GGroup;
using detail::MAction;
using detail::MGroup;
using detail::Named;
using detail::WordRef;
using program::Dialect;

constexpr double kMmPerInch = program::kMmPerInch;

enum class Motion : std::uint8_t { none, rapid, line, arc_cw, arc_ccw };
enum class Diameter : std::uint8_t { off, on, absolute_only };  // Sinumerik DIAM90: absolute only

constexpr std::uint64_t action_bit(GAction action) {
  return std::uint64_t{1} << static_cast<unsigned>(action);
}

constexpr std::uint64_t kMotionActions = action_bit(GAction::rapid) | action_bit(GAction::line) |
                                         action_bit(GAction::arc_cw) | action_bit(GAction::arc_ccw);
constexpr std::uint32_t kFeedAndSpindleLetters = detail::letter_bit('F') | detail::letter_bit('S') |
                                                 detail::letter_bit('D') | detail::letter_bit('H');

constexpr std::array<char, kAxisCount> kAxisLetters = {'X', 'Y', 'Z', 'A', 'B', 'C'};
// Fanuc lathe incremental addresses (G-code system A): U V W H for X Y Z C.
constexpr std::array<char, kAxisCount> kFanucLatheIncrements = {'U', 'V', 'W', '\0', '\0', 'H'};

class Reader {
 public:
  Reader(const ReadOptions& options, const MoveSink& sink) : options_(options), sink_(sink) {
    fanuc_lathe_ = options.dialect == Dialect::fanuc && options.kind == MachineKind::lathe;
    // Lathe controls start in the ZX plane (Fanuc T, Sinumerik turning, LinuxCNC lathe configs).
    set_plane(options.kind == MachineKind::lathe ? Plane::xz : Plane::xy);
    diameter_ = fanuc_lathe_ ? Diameter::on : Diameter::off;
    for (std::size_t axis = 0; axis < kAxisCount; ++axis) {
      axis_words_[axis] = letter(kAxisLetters[axis]);
      if (fanuc_lathe_ && kFanucLatheIncrements[axis] != '\0') {
        axis_words_[axis] |= letter(kFanucLatheIncrements[axis]);
      }
      axis_letters_ |= axis_words_[axis];
    }
  }

  std::variant<ReadSummary, ReadError> read(std::string_view text) {
    std::size_t at = 0;
    while (at < text.size() && !ended_) {
      interruption_point();
      const void* found = std::memchr(text.data() + at, '\n', text.size() - at);
      const std::size_t end =
          found == nullptr
              ? text.size()
              : static_cast<std::size_t>(static_cast<const char*>(found) - text.data());
      std::string_view line = text.substr(at, end - at);
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      ++line_;
      at = end + 1;
      detail::LexError lex_error;
      if (!detail::lex_line(line, options_.dialect, block_, lex_error)) {
        return error(lex_error.refusal, lex_error.word);
      }
      if (block_.percent) {
        // The second % closes the program (LinuxCNC, Fanuc); one before any block opens it.
        if (summary_.blocks > 0) break;
        continue;
      }
      if (!block_.has_words) continue;
      ++summary_.blocks;
      if (!execute()) return failure_;
    }
    return summary_;
  }

 private:
  // ---- errors
  bool fail(Refusal refusal, const WordRef& word) {
    failure_ = error(refusal, word);
    return false;
  }
  ReadError error(Refusal refusal, const WordRef& word) const {
    return ReadError{refusal, line_, word.column, std::string(word.text)};
  }

  // ---- the block
  bool execute() {
    offset_word_ = false;
    used_ = 0;
    named_used_ = 0;
    actions_ = 0;
    motion_word_ = nullptr;
    non_modal_word_ = nullptr;
    if (!collect_g_words() || !collect_m_words()) return false;
    if (block_.has('N')) used_ |= letter('N');
    if (block_.has('O')) {
      // Fanuc "O0001 (NAME)": the program's number, on its first block; any other O word calls
      // or defines another program (LinuxCNC o-words were refused by the lexer).
      if (options_.dialect != Dialect::fanuc || summary_.blocks != 1) {
        return fail(Refusal::subroutine_or_loop, block_.word('O'));
      }
      used_ |= letter('O');
    }
    const Diameter x_diameter_before = diameter_;
    // Most blocks of a long program are a motion word and axis words: they skip what they lack.
    const bool modes = (actions_ & ~kMotionActions) != 0 || block_.named != 0 ||
                       block_.diameter != DiameterWord::none;
    if (modes && !apply_modes()) return false;
    if ((block_.letters & kFeedAndSpindleLetters) != 0 || modes) {
      if (!apply_feed_and_spindle()) return false;
    }
    if ((block_.has('T') || has_m(MAction::tool_change)) && !tool_change()) return false;
    if (has_m(MAction::spindle_on)) spindle_on_ = true;
    if (has_m(MAction::spindle_off)) spindle_on_ = false;
    if (has(GAction::dwell) && !dwell()) return false;
    // rs274ngc reads an X word before it runs the block's G7/G8 (interp_read.cc read_x).
    x_diameter_ = options_.dialect == Dialect::linuxcnc ? x_diameter_before : diameter_;
    // machine-time.md M8: the control finishes its queued motion before a spindle, coolant or
    // offset word (LinuxCNC's task waits for motion before EMC_SPINDLE_*, EMC_COOLANT_*,
    // SET_G5X, SET_OFFSET), and these run before the block's motion (rs274ngc's order).
    if (block_.has('S') || has_m(MAction::spindle_on) || has_m(MAction::spindle_off) ||
        has_m(MAction::ignored) || offset_word_) {
      emit_point(MoveKind::sync);
    }
    if (!motion()) return false;
    if (has_m(MAction::stop)) emit_stop();
    if (has_m(MAction::end)) ended_ = true;
    return check_all_words_used();
  }

  static constexpr std::uint32_t letter(char upper) { return detail::letter_bit(upper); }
  bool has(GAction action) const { return (actions_ & action_bit(action)) != 0; }
  bool has_m(MAction action) const {
    return (m_actions_ & (1U << static_cast<unsigned>(action))) != 0;
  }
  bool is(Dialect dialect) const { return options_.dialect == dialect; }

  bool collect_g_words() {
    std::uint32_t groups = 0;
    for (std::size_t k = 0; k < block_.g_count; ++k) {
      const CodeWord& word = block_.g[k];
      const detail::GMeaning meaning =
          detail::g_meaning(options_.dialect, options_.kind, word.code);
      switch (meaning.action) {
        case GAction::canned_cycle:
          return fail(Refusal::canned_cycle, word.ref);
        case GAction::compensation_on:
          return fail(Refusal::cutter_compensation, word.ref);
        case GAction::subroutine:
          return fail(Refusal::subroutine_or_loop, word.ref);
        case GAction::unsupported:
          return fail(Refusal::unsupported_word, word.ref);
        default:
          break;
      }
      if (meaning.group != GGroup::none) {
        const std::uint32_t bit = 1U << static_cast<unsigned>(meaning.group);
        if ((groups & bit) != 0) return fail(Refusal::malformed, word.ref);  // two of one group
        groups |= bit;
      }
      if (meaning.group == GGroup::work_offset || meaning.group == GGroup::tool_length ||
          meaning.action == GAction::set_origin || meaning.action == GAction::cancel_origin) {
        offset_word_ = true;
      }
      if (meaning.group == GGroup::motion) motion_word_ = &word.ref;
      if (meaning.action == GAction::dwell || meaning.action == GAction::set_origin ||
          meaning.action == GAction::spindle_clamp) {
        non_modal_word_ = &word.ref;
      }
      actions_ |= action_bit(meaning.action);
    }
    return true;
  }

  bool collect_m_words() {
    std::uint32_t groups = 0;
    m_actions_ = 0;
    for (std::size_t k = 0; k < block_.m_count; ++k) {
      const CodeWord& word = block_.m[k];
      const detail::MMeaning meaning = detail::m_meaning(options_.dialect, word.code);
      if (meaning.action == MAction::subroutine) {
        return fail(Refusal::subroutine_or_loop, word.ref);
      }
      if (meaning.action == MAction::unsupported) return fail(Refusal::unsupported_word, word.ref);
      const std::uint32_t bit = 1U << static_cast<unsigned>(meaning.group);
      if ((groups & bit) != 0) return fail(Refusal::malformed, word.ref);
      groups |= bit;
      m_actions_ |= 1U << static_cast<unsigned>(meaning.action);
    }
    return true;
  }

  // ---- modes (rs274ngc order: feed mode, ..., plane, units, ..., path, distance)
  bool apply_modes() {
    if (has(GAction::inverse_time)) feed_mode_ = FeedMode::inverse_time;
    if (has(GAction::per_minute)) feed_mode_ = FeedMode::units_per_min;
    if (has(GAction::per_revolution)) feed_mode_ = FeedMode::per_revolution;
    if (has(GAction::plane_xy)) set_plane(Plane::xy);
    if (has(GAction::plane_xz)) set_plane(Plane::xz);
    if (has(GAction::plane_yz)) set_plane(Plane::yz);
    if (has(GAction::units_inch) || has(GAction::units_mm) || has(GAction::units_inch_geometry) ||
        has(GAction::units_mm_geometry)) {
      inch_ = has(GAction::units_inch) || has(GAction::units_inch_geometry);
      // Sinumerik G70/G71 change the geometry only; F keeps the metric unit (programs.md 3).
      feed_inch_ = has(GAction::units_inch);
      if (motion_moves_ == 0) summary_.units_stated = true;
    }
    if (has(GAction::absolute)) incremental_ = false;
    if (has(GAction::incremental)) incremental_ = true;
    if (has(GAction::arc_centre_absolute)) arc_centre_absolute_ = true;
    if (has(GAction::arc_centre_incremental)) arc_centre_absolute_ = false;
    if (has(GAction::constant_surface_speed)) constant_surface_ = true;
    if (has(GAction::constant_rpm)) constant_surface_ = false;
    if (has(GAction::diameter_on)) diameter_ = Diameter::on;
    if (has(GAction::diameter_off)) diameter_ = Diameter::off;
    switch (block_.diameter) {
      case DiameterWord::on:
        diameter_ = Diameter::on;
        break;
      case DiameterWord::off:
        diameter_ = Diameter::off;
        break;
      case DiameterWord::diam90:
        diameter_ = Diameter::absolute_only;
        break;
      case DiameterWord::none:
        break;
    }
    if (block_.has(Named::adis)) {
      adis_mm_ = block_[Named::adis] * length_scale();
      if (adis_mm_ < 0.0) return fail(Refusal::malformed, block_.word(Named::adis));
      named_used_ |= named_bit(Named::adis);
    }
    if (block_.has(Named::adispos)) named_used_ |= named_bit(Named::adispos);  // rapids' rounding
    // Fanuc G54.1 P: one of the additional work offsets, as 0 like the others.
    if (is(Dialect::fanuc) && block_.has('P') && has_code(541)) used_ |= letter('P');
    return apply_path_control();
  }

  // machine-time.md 3 M7 and 7: LinuxCNC G61.1 / G61 / G64 [P]; Fanuc G61 (its exact stop) /
  // G64; Sinumerik G60 / G64 / G641 ADIS=.
  bool apply_path_control() {
    if (has(GAction::exact_stop)) set_path(PathControl::exact_stop, false, 0.0);
    if (has(GAction::exact_path)) set_path(PathControl::exact_path, false, 0.0);
    if (has(GAction::blend_rounded)) set_path(PathControl::blend, true, 0.0);
    if (has(GAction::blend)) {
      double tolerance_mm = 0.0;
      if (is(Dialect::linuxcnc) && block_.has('P')) {
        tolerance_mm = block_['P'] * length_scale();
        if (tolerance_mm < 0.0) return fail(Refusal::malformed, block_.word('P'));
        used_ |= letter('P');
      }
      // G64 Q (naive CAM merging) stays unused and is refused as such (machine-time.md 3 M7).
      set_path(PathControl::blend, false, tolerance_mm);
    }
    return true;
  }

  void set_path(PathControl path, bool rounded, double tolerance_mm) {
    path_ = path;
    path_rounded_ = rounded;
    blend_tolerance_mm_ = tolerance_mm;
  }

  double length_scale() const { return inch_ ? kMmPerInch : 1.0; }
  static constexpr std::uint8_t named_bit(Named which) {
    return static_cast<std::uint8_t>(1U << static_cast<unsigned>(which));
  }

  // ---- F, S and the spindle clamp
  bool apply_feed_and_spindle() {
    // A Sinumerik G4 block's F and S are its dwell (seconds, revolutions), not a feed or speed.
    const bool sinumerik_dwell = is(Dialect::sinumerik) && has(GAction::dwell);
    if (block_.has('F') && !sinumerik_dwell) {
      if (block_['F'] < 0.0) return fail(Refusal::malformed, block_.word('F'));
      feed_ = block_['F'];
      feed_scale_ = feed_inch_ ? kMmPerInch : 1.0;
      used_ |= letter('F');
    }
    if (block_.has('S') && !sinumerik_dwell) {
      if (block_['S'] < 0.0) return fail(Refusal::malformed, block_.word('S'));
      const bool clamp_word = (is(Dialect::fanuc) && has(GAction::set_origin)) ||
                              (is(Dialect::sinumerik) && has(GAction::spindle_clamp));
      if (clamp_word) {
        clamp_rpm_ = block_['S'];  // Fanuc G50 S (G92 S on mills), Sinumerik G26 S
      } else {
        spindle_s_ = block_['S'];
        // G96 S: m/min, or ft/min in inch (grooving-cycle.md 5.1).
        surface_scale_ = inch_ ? program::kMPerFoot : 1.0;
      }
      used_ |= letter('S');
    }
    if (block_.has(Named::lims)) {
      if (block_[Named::lims] < 0.0) return fail(Refusal::malformed, block_.word(Named::lims));
      clamp_rpm_ = block_[Named::lims];
      named_used_ |= named_bit(Named::lims);
    }
    if (has(GAction::constant_surface_speed) && is(Dialect::linuxcnc)) {
      // LinuxCNC G96 D: the clamp of this G96 alone; without D there is none (interp_convert.cc).
      clamp_rpm_ = 0.0;
      if (block_.has('D')) {
        if (block_['D'] < 0.0) return fail(Refusal::malformed, block_.word('D'));
        clamp_rpm_ = block_['D'];
        used_ |= letter('D');
      }
    }
    // Fanuc D and Sinumerik D: the tool's offset number, no motion.
    if (block_.has('D') && !is(Dialect::linuxcnc)) used_ |= letter('D');
    // G43 H: the tool length offset, ignored (machine-time.md 4).
    if (block_.has('H') && !fanuc_lathe_ && tool_length_in_block()) {
      used_ |= letter('H');
    }
    return true;
  }

  bool tool_length_in_block() const {
    return has_code(430) || (is(Dialect::fanuc) && has_code(440));
  }

  bool has_code(int code) const {
    for (std::size_t k = 0; k < block_.g_count; ++k) {
      if (block_.g[k].code == code) return true;
    }
    return false;
  }

  // ---- tool change: M6, or the T word itself on a turret (Fanuc lathe T0707, Sinumerik lathe)
  bool tool_change() {
    bool change = has_m(MAction::tool_change);
    if (block_.has('T')) {
      used_ |= letter('T');
      const double t = block_['T'];
      if (t < 0.0) return fail(Refusal::malformed, block_.word('T'));
      if (options_.kind == MachineKind::lathe) {
        if (fanuc_lathe_) change = change || t >= 100.0;  // T{tool}{offset}: tool 0 keeps it
        if (is(Dialect::sinumerik)) change = change || t > 0.0;
      }
    }
    if (change) emit_stop();
    return true;
  }

  void emit_stop() { emit_point(MoveKind::untimed_stop); }

  // A move that goes nowhere: a stop or a flush of the queue.
  void emit_point(MoveKind kind) { sink_(point_move(kind)); }

  // A move of `kind` that stays where the tool is.
  Move point_move(MoveKind kind) const {
    Move move;
    move.kind = kind;
    move.line = line_;
    move.start = position_;
    move.end = position_;
    move.path = path_;
    return move;
  }

  // ---- G4
  bool dwell() {
    const WordRef& word = *non_modal_word_;
    double seconds = 0.0;
    switch (options_.dialect) {
      case Dialect::linuxcnc:
        if (!block_.has('P')) return fail(Refusal::malformed, word);
        seconds = block_['P'];
        used_ |= letter('P');
        break;
      case Dialect::fanuc: {
        // P in milliseconds; X (U on a lathe) in seconds.
        const int given = (block_.has('P') ? 1 : 0) + (block_.has('X') ? 1 : 0) +
                          (fanuc_lathe_ && block_.has('U') ? 1 : 0);
        if (given != 1) return fail(Refusal::malformed, word);
        if (block_.has('P')) {
          seconds = block_['P'] / 1000.0;
          used_ |= letter('P');
        } else if (block_.has('X')) {
          seconds = block_['X'];
          used_ |= letter('X');
        } else {
          seconds = block_['U'];
          used_ |= letter('U');
        }
        break;
      }
      case Dialect::sinumerik:
        if (block_.has('F') == block_.has('S')) return fail(Refusal::malformed, word);
        if (block_.has('F')) {
          seconds = block_['F'];
          used_ |= letter('F');
        } else {
          // G4 S: spindle revolutions; timed only at a known constant speed.
          const double rpm = spindle_on_ && !constant_surface_ ? spindle_s_ : 0.0;
          if (!(rpm > 0.0)) return fail(Refusal::unsupported_word, block_.word('S'));
          seconds = block_['S'] / rpm * 60.0;
          used_ |= letter('S');
        }
        break;
    }
    if (seconds < 0.0) return fail(Refusal::malformed, word);
    Move move = point_move(MoveKind::dwell);
    move.dwell_s = seconds;
    sink_(move);
    return true;
  }

  // ---- axis words
  bool axis_word_present() const { return (block_.letters & axis_letters_ & ~used_) != 0; }

  // The word a refusal of the block's motion points at: its motion word, else its first axis
  // word, else its first word.
  const WordRef& motion_ref() const {
    return motion_word_ != nullptr ? *motion_word_ : first_axis_word();
  }
  const WordRef& first_axis_word() const {
    const WordRef* first = nullptr;
    const auto consider = [&](char name) {
      if (name != '\0' && block_.has(name) &&
          (first == nullptr || block_.word(name).column < first->column)) {
        first = &block_.word(name);
      }
    };
    for (std::size_t axis = 0; axis < kAxisCount; ++axis) {
      consider(kAxisLetters[axis]);
      if (fanuc_lathe_) consider(kFanucLatheIncrements[axis]);
    }
    return first != nullptr ? *first : block_.first_word;
  }

  bool x_is_diameter(bool incremental) const {
    return x_diameter_ == Diameter::on || (x_diameter_ == Diameter::absolute_only && !incremental);
  }

  // The program value of an axis word in machine units (mm, degrees; X a radius).
  double axis_value(std::size_t axis, double value, bool incremental) const {
    if (is_rotary(axis)) return value;
    value *= length_scale();
    if (axis == index(Axis::x) && x_is_diameter(incremental)) value /= 2.0;
    return value;
  }

  // Where the block's axis words take the tool (machine-time.md 4: work offsets as 0; G92 known).
  bool target(AxisVector& end) {
    end = position_;
    // Not the words a dwell took (Fanuc G04 X, U).
    const std::uint32_t present = block_.letters & axis_letters_ & ~used_;
    if (present == 0) return true;
    for (std::size_t axis = 0; axis < kAxisCount; ++axis) {
      if ((present & axis_words_[axis]) == 0) continue;
      const char absolute_letter = kAxisLetters[axis];
      const char increment_letter = fanuc_lathe_ ? kFanucLatheIncrements[axis] : '\0';
      const bool has_absolute = (present & letter(absolute_letter)) != 0;
      const bool has_increment =
          increment_letter != '\0' && (present & letter(increment_letter)) != 0;
      if (has_absolute && has_increment) {
        return fail(Refusal::malformed, block_.word(increment_letter));  // X and U together
      }
      if (has_absolute) {
        const double value = axis_value(axis, block_[absolute_letter], incremental_);
        end[axis] = incremental_ ? position_[axis] + value : value + origin_[axis];
        used_ |= letter(absolute_letter);
      } else if (has_increment) {
        end[axis] = position_[axis] + axis_value(axis, block_[increment_letter], true);
        used_ |= letter(increment_letter);
      }
    }
    return true;
  }

  // G92 (Fanuc lathe G50): the current point gets the given coordinates; LinuxCNC G92.1 cancels.
  bool set_origin() {
    if (motion_word_ != nullptr) return fail(Refusal::malformed, *motion_word_);
    bool any = false;
    for (std::size_t axis = 0; axis < kAxisCount; ++axis) {
      const char name = kAxisLetters[axis];
      if (!block_.has(name)) continue;
      origin_[axis] = position_[axis] - axis_value(axis, block_[name], false);
      used_ |= letter(name);
      any = true;
    }
    // Fanuc G50 S / G92 S alone set the spindle clamp.
    if (!any && !(is(Dialect::fanuc) && block_.has('S'))) {
      return fail(Refusal::malformed, *non_modal_word_);
    }
    return true;
  }

  // ---- motion
  bool motion() {
    if (has(GAction::rapid)) motion_ = Motion::rapid;
    if (has(GAction::line)) motion_ = Motion::line;
    if (has(GAction::arc_cw)) motion_ = Motion::arc_cw;
    if (has(GAction::arc_ccw)) motion_ = Motion::arc_ccw;
    if (has(GAction::cancel_motion)) motion_ = Motion::none;
    if (has(GAction::cancel_origin)) origin_ = {};
    if (has(GAction::set_origin)) return set_origin();
    const bool axes = axis_word_present();
    // Sinumerik G26 with axis words sets the working area limits, not a motion.
    if (has(GAction::spindle_clamp) && axes) {
      return fail(Refusal::unsupported_word, *non_modal_word_);
    }
    const bool arc = motion_ == Motion::arc_cw || motion_ == Motion::arc_ccw;
    const bool centre_words = block_.has('I') || block_.has('J') || block_.has('K') ||
                              (block_.has('R') && !is(Dialect::sinumerik)) || block_.has(Named::cr);
    // rs274ngc: an arc needs an end or a centre; "G2 I-5" is a full circle, "G1" alone nothing.
    if (!axes && !(arc && (centre_words || motion_word_ != nullptr))) return true;
    // rs274ngc: axis words with no motion mode, or with G80.
    if (motion_ == Motion::none) return fail(Refusal::malformed, first_axis_word());
    // One Move for every block, each member set: a fresh one costs a 200-byte clear per block,
    // a third of the time of a program of arcs.
    Move& move = move_;
    if (!target(move.end)) return false;
    move.line = line_;
    move.start = position_;
    move.arc = {};
    move.feed = {};
    move.dwell_s = 0.0;
    move.path = has(GAction::exact_stop_block) ? PathControl::exact_stop : path_;
    move.blend_tolerance_mm = 0.0;
    if (move.path == PathControl::blend) {
      move.blend_tolerance_mm = path_rounded_ ? adis_mm_ : blend_tolerance_mm_;
    }
    if (motion_ == Motion::rapid) {
      move.kind = MoveKind::rapid;
    } else {
      move.kind = arc ? MoveKind::arc : MoveKind::line;
      if (!feed(move)) return false;
      if (arc && !arc_geometry(move)) return false;
    }
    emit(move);
    return true;
  }

  bool rotary_only(const Move& move) const {
    constexpr std::uint32_t kRotaryLetters = letter('A') | letter('B') | letter('C') | letter('H');
    if ((block_.letters & kRotaryLetters) == 0) return false;  // no rotary axis moved
    bool rotary = false;
    for (std::size_t axis = 0; axis < kAxisCount; ++axis) {
      if (move.start[axis] == move.end[axis]) continue;
      if (!is_rotary(axis)) return false;
      rotary = true;
    }
    return rotary;
  }

  // The feed in machine units (machine-time.md 4): mm/min (deg/min on a rotary-only move), mm/rev
  // with the spindle the move starts with, or 1/min in G93, which needs F in its own block.
  bool feed(Move& move) {
    Feed& feed = move.feed;
    feed.mode = feed_mode_;
    if (feed_mode_ == FeedMode::inverse_time) {
      if (!block_.has('F') || !(feed_ > 0.0)) return fail(Refusal::missing_feed, motion_ref());
      feed.value = feed_;
    } else {
      if (!(feed_ > 0.0)) return fail(Refusal::missing_feed, motion_ref());
      const bool raw = feed_mode_ == FeedMode::units_per_min && rotary_only(move);
      feed.value = raw ? feed_ : feed_ * feed_scale_;
    }
    if (spindle_on_) {
      if (constant_surface_) {
        feed.surface_speed_m_per_min = spindle_s_ * surface_scale_;
      } else {
        feed.spindle_rpm = spindle_s_;
      }
    }
    feed.max_spindle_rpm = clamp_rpm_ > 0.0 ? clamp_rpm_ : options_.max_spindle_rpm;
    if (feed_mode_ == FeedMode::per_revolution &&
        !(feed.spindle_rpm > 0.0 || feed.surface_speed_m_per_min > 0.0)) {
      return fail(Refusal::missing_feed, motion_ref());
    }
    return true;
  }

  struct PlaneAxes {
    std::size_t first, second;         // ArcGeometry's order
    char first_centre, second_centre;  // their centre words
    char forbidden;                    // the centre word of the normal axis
  };
  const PlaneAxes& plane_axes() const { return plane_axes_; }
  void set_plane(Plane plane) {
    plane_ = plane;
    plane_axes_ = axes_of(plane);
  }
  static PlaneAxes axes_of(Plane plane) {
    switch (plane) {
      case Plane::xz:
        return {index(Axis::z), index(Axis::x), 'K', 'I', 'J'};
      case Plane::yz:
        return {index(Axis::y), index(Axis::z), 'J', 'K', 'I'};
      case Plane::xy:
        break;
    }
    return {index(Axis::x), index(Axis::y), 'I', 'J', 'K'};
  }

  // The arc's centre and turns, checked as rs274ngc checks them (gcode_arc.h).
  bool arc_geometry(Move& move) {
    const PlaneAxes& axes = plane_axes();
    ArcGeometry& arc = move.arc;
    arc.plane = plane_;
    arc.clockwise = motion_ == Motion::arc_cw;
    const detail::PlanePoint start = {move.start[axes.first], move.start[axes.second]};
    const detail::PlanePoint end = {move.end[axes.first], move.end[axes.second]};
    const detail::ArcTolerance tolerance = detail::arc_tolerance(inch_);
    const bool has_first = block_.has(axes.first_centre);
    const bool has_second = block_.has(axes.second_centre);
    const bool r_word = block_.has('R') && !is(Dialect::sinumerik);
    const bool cr_word = block_.has(Named::cr);
    if (block_.has(axes.forbidden)) return fail(Refusal::arc_geometry, block_.word(axes.forbidden));
    if (r_word || cr_word) {
      const WordRef& radius_word = r_word ? block_.word('R') : block_.word(Named::cr);
      if (has_first || has_second) return fail(Refusal::malformed, radius_word);
      const double radius = (r_word ? block_['R'] : block_[Named::cr]) * length_scale();
      if (!detail::centre_from_radius(start, end, radius, arc.clockwise, tolerance, arc.centre)) {
        return fail(Refusal::arc_geometry, radius_word);
      }
      if (r_word) used_ |= letter('R');
      if (cr_word) named_used_ |= named_bit(Named::cr);
    } else if (has_first || has_second) {
      const bool absolute = arc_centre_absolute_;
      if (absolute && !(has_first && has_second)) {
        return fail(Refusal::arc_geometry,
                    block_.word(has_first ? axes.first_centre : axes.second_centre));
      }
      // The centre words are radius values on a lathe in every dialect (LinuxCNC read_i,
      // Fanuc and Sinumerik I/K): only X is a diameter.
      const double first = has_first ? block_[axes.first_centre] * length_scale() : 0.0;
      const double second = has_second ? block_[axes.second_centre] * length_scale() : 0.0;
      arc.centre =
          absolute ? detail::PlanePoint{first + origin_[axes.first], second + origin_[axes.second]}
                   : detail::PlanePoint{start[0] + first, start[1] + second};
      used_ |= letter(axes.first_centre) | letter(axes.second_centre);
      if (!detail::centre_fits(start, end, arc.centre, tolerance)) {
        return fail(Refusal::arc_geometry, motion_ref());
      }
    } else {
      return fail(Refusal::arc_geometry, motion_ref());
    }
    return arc_turns(arc);
  }

  // LinuxCNC P (turns, the first included), Sinumerik TURN= (extra turns).
  bool arc_turns(ArcGeometry& arc) {
    constexpr double kMostTurns = 1e6;
    if (is(Dialect::linuxcnc) && block_.has('P')) {
      const double p = block_['P'];
      if (!(p >= 1.0 && p <= kMostTurns) || p != std::floor(p)) {
        return fail(Refusal::malformed, block_.word('P'));
      }
      arc.extra_turns = static_cast<int>(p) - 1;
      used_ |= letter('P');
    }
    if (block_.has(Named::turn)) {
      const double turns = block_[Named::turn];
      if (!(turns >= 0.0 && turns <= kMostTurns) || turns != std::floor(turns)) {
        return fail(Refusal::malformed, block_.word(Named::turn));
      }
      arc.extra_turns = static_cast<int>(turns);
      named_used_ |= named_bit(Named::turn);
    }
    return true;
  }

  void emit(const Move& move) {
    if (axes_not_moved_ != 0) {
      const bool arc = move.kind == MoveKind::arc;
      const PlaneAxes& axes = plane_axes();
      for (std::size_t axis = 0; axis < kAxisCount; ++axis) {
        const bool moves = move.start[axis] != move.end[axis] ||
                           (arc && (axis == axes.first || axis == axes.second));
        if (moves && summary_.first_line_moving[axis] == 0) {
          summary_.first_line_moving[axis] = line_;
          --axes_not_moved_;
        }
      }
    }
    ++motion_moves_;
    position_ = move.end;
    sink_(move);
  }

  // rs274ngc refuses a word that nothing in its block uses; so does the reader: its meaning is
  // unknown (machine-time.md 4: "anything the reader does not know").
  bool check_all_words_used() {
    const std::uint32_t unused = block_.letters & ~used_;
    if (unused == 0 && (block_.named & ~named_used_) == 0) return true;
    const WordRef* first = nullptr;
    for (std::size_t k = 0; k < 26; ++k) {
      if ((unused & (1U << k)) != 0 && (first == nullptr || block_.ref[k].column < first->column)) {
        first = &block_.ref[k];
      }
    }
    const std::uint8_t unused_named = static_cast<std::uint8_t>(block_.named & ~named_used_);
    for (std::size_t k = 0; k < detail::kNamedCount; ++k) {
      if ((unused_named & (1U << k)) != 0 &&
          (first == nullptr || block_.named_ref[k].column < first->column)) {
        first = &block_.named_ref[k];
      }
    }
    if (first != nullptr) return fail(Refusal::unsupported_word, *first);
    return true;
  }

  const ReadOptions& options_;
  const MoveSink& sink_;
  Move move_;
  bool fanuc_lathe_ = false;
  std::uint32_t axis_letters_ = 0;                      // X Y Z A B C, and U V W H on a Fanuc lathe
  std::array<std::uint32_t, kAxisCount> axis_words_{};  // the letters of each axis
  std::size_t axes_not_moved_ = kAxisCount;

  // Reading
  Block block_;
  std::size_t line_ = 0;
  ReadSummary summary_;
  ReadError failure_;
  bool ended_ = false;
  std::size_t motion_moves_ = 0;

  // The block being run
  std::uint64_t actions_ = 0;
  std::uint32_t m_actions_ = 0;
  std::uint32_t used_ = 0;
  std::uint8_t named_used_ = 0;
  const WordRef* motion_word_ = nullptr;
  const WordRef* non_modal_word_ = nullptr;
  Diameter x_diameter_ = Diameter::off;

  // Modal state (machine-time.md 4: origin, mm, absolute, G17, G94, the default path mode)
  AxisVector position_{};
  AxisVector origin_{};  // G92
  Motion motion_ = Motion::none;
  Plane plane_ = Plane::xy;
  PlaneAxes plane_axes_{};
  bool inch_ = false;
  bool feed_inch_ = false;
  bool incremental_ = false;
  bool arc_centre_absolute_ = false;  // LinuxCNC G91.1 by default
  FeedMode feed_mode_ = FeedMode::units_per_min;
  Diameter diameter_ = Diameter::off;
  PathControl path_ = PathControl::blend;
  bool path_rounded_ = false;  // Sinumerik G641: the tolerance is ADIS
  double blend_tolerance_mm_ = 0.0;
  double adis_mm_ = 0.0;
  double feed_ = 0.0;        // F as written
  double feed_scale_ = 1.0;  // mm per program unit of F when it was written
  bool spindle_on_ = false;
  bool offset_word_ = false;  // the block has a work or tool offset word, or G92
  bool constant_surface_ = false;
  double spindle_s_ = 0.0;      // S as written: rev/min, or the surface speed under G96
  double surface_scale_ = 1.0;  // m/min per unit of S when it was written
  double clamp_rpm_ = 0.0;      // the program's spindle clamp; 0: none
};

}  // namespace

std::variant<ReadSummary, ReadError> read_program(std::string_view text, const ReadOptions& options,
                                                  const MoveSink& sink) {
  return Reader(options, sink).read(text);
}

}  // namespace cutcalc::domain::machine_time
