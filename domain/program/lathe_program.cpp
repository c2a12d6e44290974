#include "domain/program/lathe_program.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string_view>
#include <utility>

#include "domain/common/interruption.h"
#include "domain/program/block_list_writer.h"
#include "domain/program/block_words.h"
#include "domain/program/dialect_writer.h"
#include "domain/program/lathe_dialect.h"

namespace cutcalc::domain::program {
namespace {

// The words of a lathe program's parts. With no text to write to (`text_` null), a block only
// prints the words that must not print as zero: the check before the first byte is written.
class LatheWords final : public BlockWords {
 public:
  explicit LatheWords(ProgramOptions options) : BlockWords(std::move(options)) {}

  // The start and name line(s), the comments, the modal lines, the work offset, the tool call.
  void header(const LatheProgram& program, std::string& text) {
    text_ = &text;
    text += program_start(program.comments, options_);
    const char* modal = options_.dialect == Dialect::fanuc       ? program.modal.fanuc
                        : options_.dialect == Dialect::sinumerik ? program.modal.sinumerik
                                                                 : program.modal.linuxcnc;
    std::string lines = modal;
    if (const auto at = lines.find("{units}"); at != std::string::npos) {
      lines.replace(at, std::string_view("{units}").size(), lathe_units_word(options_));
    }
    line(lines);
    text += work_offset_line(options_);
    if (options_.tool_number) line(lathe_tool_call(*options_.tool_number, options_.dialect));
  }

  // The block's line(s) appended to `text`, or with `text` null only its words checked.
  void block(const LatheBlock& block, std::string* text) {
    text_ = text;
    std::visit([this](const auto& b) { this->block(b); }, block);
  }

  // The first word that printed as zero, or null.
  [[nodiscard]] const char* zero_word() const { return zero_word_; }

 private:
  using BlockWords::block;

  // A word's number, remembering the word when it prints as zero.
  std::string checked(const char* word, std::string printed) {
    if (prints_as_zero(printed) && zero_word_ == nullptr) zero_word_ = word;
    return printed;
  }
  std::string point(const LathePoint& to) const {
    std::string out;
    if (to.x_diameter_mm) out.append(" X").append(length(*to.x_diameter_mm));
    if (to.z_mm) out.append(" Z").append(length(*to.z_mm));
    if (to.c_deg) out.append(" C").append(format_fixed(*to.c_deg, decimals_));
    return out;
  }

  void block(const LatheRapid& rapid) {
    if (text_ == nullptr) return;
    line(std::string(words_.rapid) + point(rapid.to));
  }
  void block(const LatheFeed& feed) {
    const std::string f = checked("F", length(feed.feed_mm));
    if (text_ == nullptr) return;
    feed_line(std::string(words_.feed) + point(feed.to), f);
  }
  void block(const FeedModeChange& change) {
    if (text_ == nullptr) return;
    line(change.mode == FeedMode::inverse_time ? "G93" : "G94");
    forget_feed();
  }
  void block(const InverseTimeFeed& feed) {
    const std::string f = checked("F", format_fixed(feed.per_minute, decimals_));
    if (text_ == nullptr) return;
    line(std::string(words_.feed) + point(feed.to) + " F" + f);
  }
  void block(const ConstantSpindleSpeed& spindle) {
    const std::string s = checked("S", options_.dialect == Dialect::fanuc
                                           ? format_fixed(fanuc_spindle_words(spindle).s, 0)
                                           : format_fixed(spindle.rpm, decimals_));
    if (text_ == nullptr) return;
    line("G97 S" + s + " " + words_.spindle_on);
  }
  void block(const ConstantSurfaceSpeed& spindle) {
    const double v =
        surface_speed_in_program_units(spindle.cutting_speed_m_per_min, options_.units);
    switch (options_.dialect) {
      case Dialect::fanuc: {
        const FanucSpindleWords words = fanuc_spindle_words(spindle, options_.units);
        const std::string clamp = checked("G50 S", format_fixed(words.clamp_rpm.value_or(0.0), 0));
        const std::string s = checked("S", format_fixed(words.s, 0));
        if (text_ == nullptr) return;
        line("G50 S" + clamp);
        line("G96 S" + s + " " + words_.spindle_on);
        return;
      }
      case Dialect::sinumerik: {
        const std::string s = checked("S", format_fixed(v, decimals_));
        const std::string lims = checked("LIMS", format_fixed(spindle.max_rpm, decimals_));
        if (text_ == nullptr) return;
        line("G96 S" + s + " LIMS=" + lims + " " + words_.spindle_on);
        return;
      }
      case Dialect::linuxcnc: {
        const std::string d = checked("D", format_fixed(spindle.max_rpm, decimals_));
        const std::string s = checked("S", format_fixed(v, decimals_));
        if (text_ == nullptr) return;
        line("G96 D" + d + " S" + s + " " + words_.spindle_on);
        return;
      }
    }
  }
  void block(const Dwell& dwell) {
    const std::string seconds = checked("G4", format_fixed(dwell.seconds, kDwellDecimals));
    if (text_ == nullptr) return;
    line(std::string(lathe_facts(options_.dialect).dwell_word) + seconds);
  }
  const char* zero_word_ = nullptr;
};

// A lathe program's text, written as it is read: the header, the blocks from the next one on, the
// end. Its words were checked first (lathe_program_error): none prints as zero.
class LatheProgramWriter final : public BlockListWriter {
 public:
  LatheProgramWriter(std::shared_ptr<const LatheProgram> program, ProgramOptions options)
      : program_(std::move(program)), words_(std::move(options)) {}

  [[nodiscard]] std::size_t held_bytes() const override {
    return sizeof(*this) + words_.held_bytes() + program::held_bytes(*program_);
  }

 private:
  void write_header(std::string& text) override { words_.header(*program_, text); }
  [[nodiscard]] std::size_t block_count() const override { return program_->blocks.size(); }
  void write_block(std::size_t index, std::string& text) override {
    words_.block(program_->blocks[index], &text);
  }
  void write_end(std::string& text) override { text += program_end(words_.options()); }

  std::shared_ptr<const LatheProgram> program_;
  LatheWords words_;
};

}  // namespace

double surface_speed_in_program_units(double cutting_speed_m_per_min, Units units) {
  return units == Units::inch ? cutting_speed_m_per_min / kMPerFoot : cutting_speed_m_per_min;
}

FanucSpindleWords fanuc_spindle_words(const ConstantSpindleSpeed& spindle) {
  FanucSpindleWords words;
  words.s = fanuc_s_value(spindle.rpm);
  words.rounded = fanuc_s_rounds(spindle.rpm);
  return words;
}

FanucSpindleWords fanuc_spindle_words(const ConstantSurfaceSpeed& spindle, Units units) {
  const double v = surface_speed_in_program_units(spindle.cutting_speed_m_per_min, units);
  FanucSpindleWords words;
  words.s = fanuc_s_value(v);
  words.clamp_rpm = std::floor(spindle.max_rpm);  // never above the limit
  words.rounded = fanuc_s_rounds(v) || std::fabs(*words.clamp_rpm - spindle.max_rpm) > 1e-9;
  return words;
}

std::optional<DomainError> lathe_program_error(const LatheProgram& program,
                                               const ProgramOptions& options) {
  LatheWords words(options);
  for (const LatheBlock& block : program.blocks) {
    interruption_point();
    words.block(block, nullptr);
    if (const char* word = words.zero_word()) {
      return make_error(ErrorCode::word_prints_as_zero,
                        std::string(word) + " would print as zero with these decimals");
    }
  }
  return std::nullopt;
}

std::unique_ptr<TextSource> open_lathe_program(std::shared_ptr<const LatheProgram> program,
                                               ProgramOptions options) {
  return std::make_unique<LatheProgramWriter>(std::move(program), std::move(options));
}

Result<std::string> write_lathe_program(const LatheProgram& program,
                                        const ProgramOptions& options) {
  if (auto error = lathe_program_error(program, options)) return std::move(*error);
  // The program outlives the source here: held without being owned.
  const std::shared_ptr<const LatheProgram> unowned(std::shared_ptr<const LatheProgram>(),
                                                    &program);
  std::string text;
  write_all(*open_lathe_program(unowned, options), text);
  return text;
}

Result<LatheProgramFile> lathe_program_file(LatheProgram program, const ProgramOptions& options) {
  if (auto error = lathe_program_error(program, options)) return std::move(*error);
  return LatheProgramFile{std::make_shared<const LatheProgram>(std::move(program)), options,
                          file_name(options)};
}

std::unique_ptr<TextSource> open_program_text(const LatheProgramFile& file) {
  return open_lathe_program(file.program, file.options);
}

std::string program_text(const LatheProgramFile& file) {
  std::string text;
  write_all(*open_program_text(file), text);
  return text;
}

std::size_t held_bytes(const LatheProgram& program) {
  std::size_t bytes = sizeof(program) + program.comments.capacity() * sizeof(std::string) +
                      program.blocks.capacity() * sizeof(LatheBlock);
  for (const std::string& comment : program.comments) bytes += comment.capacity();
  return bytes;
}

}  // namespace cutcalc::domain::program
