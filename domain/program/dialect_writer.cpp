#include "domain/program/dialect_writer.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <memory>
#include <utility>

#include "domain/common/ascii_text.h"
#include "domain/program/block_list_writer.h"
#include "domain/program/block_words.h"

namespace cutcalc::domain::program {
namespace {

// Concatenation by append: GCC 12 at -O3 reports a false -Wrestrict on `"literal" + std::string`.
std::string cat(std::initializer_list<std::string_view> parts) {
  std::string out;
  for (const std::string_view part : parts) out.append(part);
  return out;
}

// The words of a milling program's blocks (section 3), appended to the text of the block.
class MillingWords final : public BlockWords {
 public:
  explicit MillingWords(ProgramOptions options) : BlockWords(std::move(options)) {}

  void block(const Block& block, std::string& text) {
    text_ = &text;
    std::visit([this](const auto& b) { this->block(b); }, block);
  }

 private:
  using BlockWords::block;

  std::string axes(const Axes& to) const {
    std::string out;
    if (to.x_mm) out.append(" X").append(length(*to.x_mm));
    if (to.y_mm) out.append(" Y").append(length(*to.y_mm));
    if (to.z_mm) out.append(" Z").append(length(*to.z_mm));
    return out;
  }

  void block(const SafeStart& start) { *text_ += safe_start_text(start, options_); }
  void block(const Rapid& rapid) { line(cat({words_.rapid, axes(rapid.to)})); }
  void block(const Feed& feed) {
    feed_line(cat({words_.feed, axes(feed.to)}), length(feed.feed_mm_per_min));
  }
  void block(const SpindleOn& on) {
    line(cat({"S", spindle_text(on.rpm, options_.dialect, decimals_), " ", words_.spindle_on}));
  }
  void block(const SpeedChange& change) {
    line(cat({"S", spindle_text(change.rpm, options_.dialect, decimals_)}));
  }
};

// Section 3's text of a model, written as it is read: the header, the blocks from the next one on
// (the last printed F carried from block to block), the end.
class ProgramWriter final : public BlockListWriter {
 public:
  ProgramWriter(std::shared_ptr<const ProgramModel> model, ProgramOptions options)
      : model_(std::move(model)), words_(std::move(options)) {}

  [[nodiscard]] std::size_t held_bytes() const override {
    return sizeof(*this) + words_.held_bytes() + program::held_bytes(*model_);
  }

 private:
  void write_header(std::string& text) override {
    text += program_header(model_->comments, words_.options());
  }
  [[nodiscard]] std::size_t block_count() const override { return model_->blocks.size(); }
  void write_block(std::size_t index, std::string& text) override {
    words_.block(model_->blocks[index], text);
  }
  void write_end(std::string& text) override { text += program_end(words_.options()); }

  std::shared_ptr<const ProgramModel> model_;
  MillingWords words_;
};

}  // namespace

std::string format_fixed(double value, int decimals) {
  std::array<char, 400> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                    std::chars_format::fixed, decimals);
  std::string text(buffer.data(), result.ptr);
  if (!text.empty() && text.front() == '-' &&
      text.find_first_not_of("0.", 1) == std::string::npos) {
    text.erase(0, 1);
  }
  return text;
}

bool prints_as_zero(std::string_view printed) {
  return printed.find_first_not_of("0.") == std::string_view::npos;
}

double to_program_units(double mm, Units units) {
  return units == Units::inch ? mm / kMmPerInch : mm;
}

double fanuc_s_value(double value) { return std::floor(value + 0.5); }

bool fanuc_s_rounds(double value) { return std::fabs(fanuc_s_value(value) - value) > 1e-9; }

std::string spindle_text(double rpm, Dialect dialect, int decimals) {
  if (dialect == Dialect::fanuc) return format_fixed(fanuc_s_value(rpm), 0);
  return format_fixed(rpm, decimals);
}

const DialectWords& words_of(Dialect dialect) {
  static constexpr DialectWords kShort{"G0", "G1", "G3", "M3", "M5", "M8", "M7", "M9", "M6"};
  static constexpr DialectWords kFanuc{"G00", "G01", "G03", "M03", "M05",
                                       "M08", "M07", "M09", "M06"};
  return dialect == Dialect::fanuc ? kFanuc : kShort;
}

namespace {

std::string comment_line(std::string_view text, Dialect dialect) {
  const std::string body = comment_text(text, dialect);
  return dialect == Dialect::sinumerik ? cat({"; ", body, "\n"}) : cat({"(", body, ")\n"});
}

}  // namespace

std::string program_start(const std::vector<std::string>& comments, const ProgramOptions& options) {
  std::string out;
  switch (options.dialect) {
    case Dialect::linuxcnc:
      out = cat({"%\n(", options.name, ")\n"});
      break;
    case Dialect::fanuc: {
      std::array<char, 16> number{};
      std::snprintf(number.data(), number.size(), "O%04d", options.program_number);
      out = cat({"%\n", number.data(), " (", options.name, ")\n"});
      break;
    }
    case Dialect::sinumerik:
      out = cat({"; ", options.name, "\n"});
      break;
  }
  for (const auto& text : comments) out += comment_line(text, options.dialect);
  return out;
}

std::string program_header(const std::vector<std::string>& comments,
                           const ProgramOptions& options) {
  const bool inch = options.units == Units::inch;
  std::string out = program_start(comments, options);
  switch (options.dialect) {
    case Dialect::linuxcnc:
      out += cat({inch ? "G20" : "G21", " G17 G90 G40 G49 G80 G94\n"});
      break;
    case Dialect::fanuc:
      out += cat({inch ? "G20" : "G21", "\nG17 G40 G49 G80 G90 G94\n"});
      break;
    case Dialect::sinumerik:
      out += cat({"G17 ", inch ? "G700" : "G710", " G40 G90 G94\n"});
      break;
  }
  return out + work_offset_line(options);
}

std::string work_offset_line(const ProgramOptions& options) {
  return cat({"G", std::to_string(options.work_offset), "\n"}) + path_control_lines(options);
}

// machine-time.md section 7: the mode in each dialect. Fanuc has no separate exact path mode and
// sets its blending tolerance in parameters; Sinumerik blends within ADIS under G641.
std::string path_control_lines(const ProgramOptions& options) {
  if (!options.path_control) return {};
  const PathControl& control = *options.path_control;
  // Never printed as 0 (LinuxCNC's G64 P0 is no tolerance at all): at least one unit of the last
  // decimal, the finest the program can state.
  const auto tolerance = [&] {
    const double least = std::pow(10.0, -decimals_of(options));
    return format_fixed(std::max(to_program_units(*control.tolerance_mm, options.units), least),
                        decimals_of(options));
  };
  switch (control.mode) {
    case PathMode::exact_stop:
      return options.dialect == Dialect::linuxcnc ? "G61.1\n"
             : options.dialect == Dialect::fanuc  ? "G61\n"
                                                  : "G60\n";
    case PathMode::exact_path:
      return options.dialect == Dialect::sinumerik ? "G60\n" : "G61\n";
    case PathMode::blend:
      break;
  }
  if (!control.tolerance_mm) return "G64\n";
  switch (options.dialect) {
    case Dialect::linuxcnc:
      return cat({"G64 P", tolerance(), "\n"});
    case Dialect::fanuc:
      return cat({"G64\n", comment_line("BLEND TOLERANCE " + tolerance() +
                                            (options.units == Units::inch ? " IN" : " MM") +
                                            " IS SET IN THE CONTROL PARAMETERS",
                                        Dialect::fanuc)});
    case Dialect::sinumerik:
      return cat({"G641 ADIS=", tolerance(), "\n"});
  }
  return {};
}

std::string safe_start_text(const SafeStart& start, const ProgramOptions& options) {
  const DialectWords& words = words_of(options.dialect);
  const std::string z =
      format_fixed(to_program_units(start.safe_z_mm, options.units), decimals_of(options));
  const std::string tool = start.tool_number ? std::to_string(*start.tool_number) : "";
  if (options.dialect == Dialect::sinumerik) {
    std::string out;
    if (start.tool_number) out += cat({"T", tool, "\n", words.tool_change, "\n"});
    out += start.tool_length_offset ? "D1\n" : "D0\n";
    return out + cat({words.rapid, " Z", z, "\n"});
  }
  std::string out;
  if (start.tool_number) out += cat({"T", tool, " ", words.tool_change, "\n"});
  if (start.tool_length_offset && start.tool_number) {
    return out + cat({words.rapid, " G43 Z", z, " H", tool, "\n"});
  }
  return out + cat({words.rapid, " Z", z, "\n"});
}

std::string program_end(const ProgramOptions& options) {
  return options.dialect == Dialect::sinumerik ? "M30\n" : "M30\n%\n";
}

std::size_t held_bytes(const ProgramModel& model) {
  std::size_t bytes = sizeof(model) + model.comments.capacity() * sizeof(std::string) +
                      model.blocks.capacity() * sizeof(Block);
  for (const std::string& comment : model.comments) bytes += comment.capacity();
  return bytes;
}

std::unique_ptr<TextSource> open_program(std::shared_ptr<const ProgramModel> model,
                                         ProgramOptions options) {
  return std::make_unique<ProgramWriter>(std::move(model), std::move(options));
}

std::string write_program(const ProgramModel& model, const ProgramOptions& options) {
  // The model outlives the source here: held without being owned.
  const std::shared_ptr<const ProgramModel> unowned(std::shared_ptr<const ProgramModel>(), &model);
  std::string text;
  write_all(*open_program(unowned, options), text);
  return text;
}

std::string comment_text(std::string_view text, Dialect dialect) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    if (c == '(' || c == ')' || c == ';' || c == '%') c = ' ';
    if (dialect == Dialect::fanuc) c = ascii_upper(c);
    out.push_back(c);
  }
  return out;
}

}  // namespace cutcalc::domain::program
