#include "domain/program/dialect_writer.h"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <initializer_list>

namespace cutcalc::domain::program {
namespace {

// The words each dialect writes for the same thing (section 3 table).
struct DialectWords {
  const char* rapid;        // G0 / G00
  const char* feed;         // G1 / G01
  const char* spindle_on;   // M3 / M03
  const char* spindle_off;  // M5 / M05
  const char* flood;        // M8 / M08
  const char* mist;         // M7 / M07
  const char* coolant_off;  // M9 / M09
  const char* tool_change;  // M6 / M06
};

const DialectWords& words_of(Dialect dialect) {
  static constexpr DialectWords kShort{"G0", "G1", "M3", "M5", "M8", "M7", "M9", "M6"};
  static constexpr DialectWords kFanuc{"G00", "G01", "M03", "M05", "M08", "M07", "M09", "M06"};
  return dialect == Dialect::fanuc ? kFanuc : kShort;
}

// Concatenation by append: GCC 12 at -O3 reports a false -Wrestrict on `"literal" + std::string`.
std::string cat(std::initializer_list<std::string_view> parts) {
  std::string out;
  for (const std::string_view part : parts) out.append(part);
  return out;
}

class Writer {
 public:
  Writer(const ProgramOptions& options)
      : options_(options), decimals_(decimals_of(options)), words_(words_of(options.dialect)) {}

  std::string write(const ProgramModel& model) {
    header(model);
    for (const Block& block : model.blocks) {
      std::visit([this](const auto& b) { this->block(b); }, block);
    }
    end();
    return std::move(text_);
  }

 private:
  void line(std::string_view text) {
    text_.append(text);
    text_.push_back('\n');
  }
  void comment(std::string_view text) {
    const std::string body = comment_text(text, options_.dialect);
    line(options_.dialect == Dialect::sinumerik ? cat({"; ", body}) : cat({"(", body, ")"}));
  }
  std::string number(double mm) const {
    return format_fixed(to_program_units(mm, options_.units), decimals_);
  }
  std::string axes(const Axes& to) const {
    std::string out;
    if (to.x_mm) out.append(" X").append(number(*to.x_mm));
    if (to.y_mm) out.append(" Y").append(number(*to.y_mm));
    if (to.z_mm) out.append(" Z").append(number(*to.z_mm));
    return out;
  }
  std::string work_offset() const { return cat({"G", std::to_string(options_.work_offset)}); }

  void header(const ProgramModel& model) {
    const bool inch = options_.units == Units::inch;
    switch (options_.dialect) {
      case Dialect::linuxcnc:
        line("%");
        line(cat({"(", options_.name, ")"}));
        for (const auto& text : model.comments) comment(text);
        line(cat({inch ? "G20" : "G21", " G17 G90 G40 G49 G80 G94"}));
        break;
      case Dialect::fanuc: {
        line("%");
        std::array<char, 16> number{};
        std::snprintf(number.data(), number.size(), "O%04d", options_.program_number);
        line(cat({number.data(), " (", options_.name, ")"}));
        for (const auto& text : model.comments) comment(text);
        line(inch ? "G20" : "G21");
        line("G17 G40 G49 G80 G90 G94");
        break;
      }
      case Dialect::sinumerik:
        line(cat({"; ", options_.name}));
        for (const auto& text : model.comments) comment(text);
        line(cat({"G17 ", inch ? "G700" : "G710", " G40 G90 G94"}));
        break;
    }
    line(work_offset());
  }

  void end() {
    line("M30");
    if (options_.dialect != Dialect::sinumerik) line("%");
  }

  void block(const SafeStart& start) {
    const std::string z = number(start.safe_z_mm);
    const std::string tool = start.tool_number ? std::to_string(*start.tool_number) : "";
    if (options_.dialect == Dialect::sinumerik) {
      if (start.tool_number) {
        line(cat({"T", tool}));
        line(words_.tool_change);
      }
      line(start.tool_length_offset ? "D1" : "D0");
      line(cat({words_.rapid, " Z", z}));
      return;
    }
    if (start.tool_number) line(cat({"T", tool, " ", words_.tool_change}));
    if (start.tool_length_offset && start.tool_number) {
      line(cat({words_.rapid, " G43 Z", z, " H", tool}));
    } else {
      line(cat({words_.rapid, " Z", z}));
    }
  }
  void block(const Rapid& rapid) { line(cat({words_.rapid, axes(rapid.to)})); }
  void block(const Feed& feed) {
    std::string text = cat({words_.feed, axes(feed.to)});
    const std::string f = number(feed.feed_mm_per_min);
    if (f != last_feed_) {
      text.append(" F").append(f);
      last_feed_ = f;
    }
    line(text);
  }
  void block(const SpindleOn& on) {
    line(cat({"S", spindle_text(on.rpm, options_.dialect, decimals_), " ", words_.spindle_on}));
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

double to_program_units(double mm, Units units) {
  return units == Units::inch ? mm / kMmPerInch : mm;
}

std::string spindle_text(double rpm, Dialect dialect, int decimals) {
  if (dialect == Dialect::fanuc) return format_fixed(std::floor(rpm + 0.5), 0);
  return format_fixed(rpm, decimals);
}

std::string write_program(const ProgramModel& model, const ProgramOptions& options) {
  return Writer(options).write(model);
}

std::string comment_text(std::string_view text, Dialect dialect) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    if (c == '(' || c == ')' || c == ';' || c == '%') c = ' ';
    if (dialect == Dialect::fanuc && c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
    out.push_back(c);
  }
  return out;
}

}  // namespace cutcalc::domain::program
