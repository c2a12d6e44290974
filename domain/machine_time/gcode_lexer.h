#pragma once
// One line of a G-code program split into its words (spec machine-time.md section 4): the syntax
// of the three dialects (comments, numbers, Sinumerik's keywords and `=` words), nothing of their
// meaning. What no dialect reader could time (parameters, expressions, subroutine calls, cycles
// by name) is refused here already, with the column and the text of the word. No allocation: the
// words point into the program text.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "domain/machine_time/gcode_reader.h"

namespace cutcalc::domain::machine_time::detail {

struct WordRef {
  std::size_t column = 0;  // 1-based
  std::string_view text;   // as written, e.g. "G01", "X-1.5", "LIMS=3000"
};

struct CodeWord {
  int code = 0;  // the G or M number times 10: G61.1 -> 611, G01 -> 10
  WordRef ref;
};

// Sinumerik's named value words (KEYWORD=value).
enum class Named : std::uint8_t { lims, adis, adispos, cr, turn };
inline constexpr std::size_t kNamedCount = 5;

enum class DiameterWord : std::uint8_t { none, on, off, diam90 };  // Sinumerik DIAMON/DIAMOF/DIAM90

constexpr std::size_t letter_index(char upper) { return static_cast<std::size_t>(upper - 'A'); }
constexpr std::uint32_t letter_bit(char upper) { return std::uint32_t{1} << letter_index(upper); }

struct Block {
  static constexpr std::size_t kMaxCodes = 16;

  std::uint32_t letters = 0;  // bit letter_bit(L): the single-letter word L is present
  std::array<double, 26> value{};
  std::array<WordRef, 26> ref{};
  std::array<CodeWord, kMaxCodes> g{};
  std::size_t g_count = 0;
  std::array<CodeWord, kMaxCodes> m{};
  std::size_t m_count = 0;
  std::uint8_t named = 0;  // bit per Named
  std::array<double, kNamedCount> named_value{};
  std::array<WordRef, kNamedCount> named_ref{};
  DiameterWord diameter = DiameterWord::none;
  WordRef first_word;      // for refusals that concern the block as a whole
  bool has_words = false;  // machine-time.md 6 `blocks`: a line with at least one word
  bool percent = false;    // a `%` line: program start or end

  bool has(char upper) const { return (letters & letter_bit(upper)) != 0; }
  double operator[](char upper) const { return value[letter_index(upper)]; }
  const WordRef& word(char upper) const { return ref[letter_index(upper)]; }
  bool has(Named which) const { return (named & (1U << static_cast<unsigned>(which))) != 0; }
  double operator[](Named which) const { return named_value[static_cast<std::size_t>(which)]; }
  const WordRef& word(Named which) const { return named_ref[static_cast<std::size_t>(which)]; }

  void clear() {
    letters = 0;
    g_count = 0;
    m_count = 0;
    named = 0;
    diameter = DiameterWord::none;
    first_word = {};
    has_words = false;
    percent = false;
  }
};

struct LexError {
  Refusal refusal = Refusal::malformed;
  WordRef word;
};

// Splits `line` (no line end) into `block` (cleared first). False: `error` says why the line
// cannot be read.
bool lex_line(std::string_view line, program::Dialect dialect, Block& block, LexError& error);

// A real number as G-code writes it: [+-] digits [. digits] or [+-] . digits (no exponent, no
// inf/nan), and its `value` (infinite when out of range). Returns the end of the number, or
// `begin` when there is none.
const char* scan_number(const char* begin, const char* end, double& value);

}  // namespace cutcalc::domain::machine_time::detail
