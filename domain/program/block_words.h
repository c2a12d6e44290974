#pragma once
// What the milling (dialect_writer) and lathe (lathe_program) writers print the same way: a line,
// a length in the program's units, the modal F word, and the spindle-off and coolant blocks. Each
// writer's visitor derives from it and adds the blocks only it has.

#include <cstddef>
#include <string>
#include <string_view>

#include "domain/program/dialect_writer.h"
#include "domain/program/program_model.h"
#include "domain/program/program_options.h"

namespace cutcalc::domain::program {

class BlockWords {
 public:
  [[nodiscard]] const ProgramOptions& options() const { return options_; }
  // What the words hold beyond their own size, in bytes (for a memory budget).
  [[nodiscard]] std::size_t held_bytes() const;

  BlockWords(const BlockWords&) = delete;
  BlockWords& operator=(const BlockWords&) = delete;

 protected:
  explicit BlockWords(ProgramOptions options);

  void line(std::string_view text);
  // A length or feed in mm, printed in the program's units with its decimals.
  [[nodiscard]] std::string length(double mm) const;
  // A feed move's line: `move` with " F" and `printed_feed` when it differs from the last one.
  void feed_line(std::string move, const std::string& printed_feed);
  // The F word is printed again on the next feed move (a new feed mode).
  void forget_feed() { last_feed_.clear(); }

  // Blocks both writers have; nothing is written while `text_` is null.
  void block(const SpindleOff&);
  void block(const CoolantOn& on);
  void block(const CoolantOff&);

  ProgramOptions options_;
  int decimals_;
  const DialectWords& words_;
  std::string* text_ = nullptr;  // where the lines go

 private:
  std::string last_feed_;  // printed; empty before the first feed move
};

}  // namespace cutcalc::domain::program
