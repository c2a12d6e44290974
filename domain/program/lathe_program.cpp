#include "domain/program/lathe_program.h"

#include <cmath>
#include <string_view>

#include "domain/common/interruption.h"
#include "domain/program/dialect_writer.h"
#include "domain/program/lathe_dialect.h"

namespace cutcalc::domain::program {
namespace {

class LatheWriter {
 public:
  explicit LatheWriter(const ProgramOptions& options)
      : options_(options), decimals_(decimals_of(options)), words_(words_of(options.dialect)) {}

  Result<std::string> write(const LatheProgram& program) {
    header(program);
    for (const LatheBlock& block : program.blocks) {
      interruption_point();
      std::visit([this](const auto& b) { this->block(b); }, block);
      if (zero_word_) {
        return make_error(ErrorCode::word_prints_as_zero,
                          std::string(zero_word_) + " would print as zero with these decimals");
      }
    }
    text_ += program_end(options_);
    return std::move(text_);
  }

 private:
  void line(std::string_view text) {
    text_.append(text);
    text_.push_back('\n');
  }
  // A word's number, remembering the word when it prints as zero.
  std::string checked(const char* word, std::string printed) {
    if (prints_as_zero(printed) && zero_word_ == nullptr) zero_word_ = word;
    return printed;
  }
  std::string length(double mm) const {
    return format_fixed(to_program_units(mm, options_.units), decimals_);
  }
  std::string point(const LathePoint& to) const {
    std::string out;
    if (to.x_diameter_mm) out.append(" X").append(length(*to.x_diameter_mm));
    if (to.z_mm) out.append(" Z").append(length(*to.z_mm));
    if (to.c_deg) out.append(" C").append(format_fixed(*to.c_deg, decimals_));
    return out;
  }

  void header(const LatheProgram& program) {
    text_ += program_start(program.comments, options_);
    const char* modal = options_.dialect == Dialect::fanuc       ? program.modal.fanuc
                        : options_.dialect == Dialect::sinumerik ? program.modal.sinumerik
                                                                 : program.modal.linuxcnc;
    std::string lines = modal;
    if (const auto at = lines.find("{units}"); at != std::string::npos) {
      lines.replace(at, std::string_view("{units}").size(), lathe_units_word(options_));
    }
    line(lines);
    text_ += work_offset_line(options_);
    if (options_.tool_number) line(lathe_tool_call(*options_.tool_number, options_.dialect));
  }

  void block(const LatheRapid& rapid) { line(std::string(words_.rapid) + point(rapid.to)); }
  void block(const LatheFeed& feed) {
    std::string text = std::string(words_.feed) + point(feed.to);
    const std::string f = checked("F", length(feed.feed_mm));
    if (f != last_feed_) {
      text.append(" F").append(f);
      last_feed_ = f;
    }
    line(text);
  }
  void block(const FeedModeChange& change) {
    line(change.mode == FeedMode::inverse_time ? "G93" : "G94");
    last_feed_.clear();
  }
  void block(const InverseTimeFeed& feed) {
    line(std::string(words_.feed) + point(feed.to) + " F" +
         checked("F", format_fixed(feed.per_minute, decimals_)));
  }
  void block(const ConstantSpindleSpeed& spindle) {
    const std::string s = options_.dialect == Dialect::fanuc
                              ? format_fixed(fanuc_spindle_words(spindle).s, 0)
                              : format_fixed(spindle.rpm, decimals_);
    line("G97 S" + checked("S", s) + " " + words_.spindle_on);
  }
  void block(const ConstantSurfaceSpeed& spindle) {
    const double v =
        surface_speed_in_program_units(spindle.cutting_speed_m_per_min, options_.units);
    switch (options_.dialect) {
      case Dialect::fanuc: {
        const FanucSpindleWords words = fanuc_spindle_words(spindle, options_.units);
        line("G50 S" + checked("G50 S", format_fixed(words.clamp_rpm.value_or(0.0), 0)));
        line("G96 S" + checked("S", format_fixed(words.s, 0)) + " " + words_.spindle_on);
        return;
      }
      case Dialect::sinumerik:
        line("G96 S" + checked("S", format_fixed(v, decimals_)) + " LIMS=" +
             checked("LIMS", format_fixed(spindle.max_rpm, decimals_)) + " " + words_.spindle_on);
        return;
      case Dialect::linuxcnc:
        line("G96 D" + checked("D", format_fixed(spindle.max_rpm, decimals_)) + " S" +
             checked("S", format_fixed(v, decimals_)) + " " + words_.spindle_on);
        return;
    }
  }
  void block(const Dwell& dwell) {
    line(std::string(lathe_facts(options_.dialect).dwell_word) +
         checked("G4", format_fixed(dwell.seconds, kDwellDecimals)));
  }
  void block(const SpindleOff&) { line(words_.spindle_off); }
  void block(const CoolantOn& on) {
    line(on.coolant == Coolant::mist ? words_.mist : words_.flood);
  }
  void block(const CoolantOff&) { line(words_.coolant_off); }

  const ProgramOptions& options_;
  int decimals_;
  const DialectWords& words_;
  std::string text_;
  std::string last_feed_;  // printed; empty before the first feed move
  const char* zero_word_ = nullptr;
};

}  // namespace

double surface_speed_in_program_units(double cutting_speed_m_per_min, Units units) {
  return units == Units::inch ? cutting_speed_m_per_min / kMPerFoot : cutting_speed_m_per_min;
}

FanucSpindleWords fanuc_spindle_words(const ConstantSpindleSpeed& spindle) {
  FanucSpindleWords words;
  words.s = std::floor(spindle.rpm + 0.5);
  words.rounded = std::fabs(words.s - spindle.rpm) > 1e-9;
  return words;
}

FanucSpindleWords fanuc_spindle_words(const ConstantSurfaceSpeed& spindle, Units units) {
  const double v = surface_speed_in_program_units(spindle.cutting_speed_m_per_min, units);
  FanucSpindleWords words;
  words.s = std::floor(v + 0.5);
  words.clamp_rpm = std::floor(spindle.max_rpm);  // never above the limit
  words.rounded =
      std::fabs(words.s - v) > 1e-9 || std::fabs(*words.clamp_rpm - spindle.max_rpm) > 1e-9;
  return words;
}

Result<std::string> write_lathe_program(const LatheProgram& program,
                                        const ProgramOptions& options) {
  return LatheWriter(options).write(program);
}

}  // namespace cutcalc::domain::program
