// machine-time.md section 4: the words of a line in LinuxCNC, Fanuc and Sinumerik syntax.

#include "domain/machine_time/gcode_lexer.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <string_view>
#include <system_error>

#include "domain/common/ascii_text.h"

namespace cutcalc::domain::machine_time::detail {
namespace {

using program::Dialect;

constexpr bool is_digit(char c) { return c >= '0' && c <= '9'; }
constexpr bool is_alpha(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
constexpr bool is_identifier(char c) { return is_alpha(c) || is_digit(c) || c == '_'; }
constexpr bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

// Larger numbers are typing errors, and would overflow the planner's squares.
constexpr double kLargestNumber = 1e12;

// Powers of ten that a double holds exactly: mantissa / 10^k is then correctly rounded.
constexpr std::array<double, 23> kPow10 = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                           1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                           1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

bool equals_upper(std::string_view text, std::string_view upper_word) {
  if (text.size() != upper_word.size()) return false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (ascii_upper(text[i]) != upper_word[i]) return false;
  }
  return true;
}

bool starts_upper(std::string_view text, std::string_view upper_prefix) {
  return text.size() >= upper_prefix.size() &&
         equals_upper(text.substr(0, upper_prefix.size()), upper_prefix);
}

bool any_of_upper(std::string_view text, std::initializer_list<std::string_view> words) {
  for (const std::string_view word : words) {
    if (equals_upper(text, word)) return true;
  }
  return false;
}

// scan_number, inlined into the lexer: a call per number is a tenth of a program's reading.
inline const char* scan(const char* begin, const char* end, double& value) {
  const char* at = begin;
  const bool negative = at != end && *at == '-';
  if (at != end && (*at == '+' || *at == '-')) ++at;
  // Up to 15 digits in an integer mantissa, divided once by an exact power of ten: correctly
  // rounded, and several times faster than the general conversion, which takes longer numbers.
  const char* digits = at;
  std::uint64_t mantissa = 0;
  while (at != end && is_digit(*at)) {
    mantissa = mantissa * 10 + static_cast<std::uint64_t>(*at - '0');
    ++at;
  }
  std::size_t count = static_cast<std::size_t>(at - digits);
  std::size_t fraction = 0;
  if (at != end && *at == '.') {
    const char* fraction_digits = ++at;
    while (at != end && is_digit(*at)) {
      mantissa = mantissa * 10 + static_cast<std::uint64_t>(*at - '0');
      ++at;
    }
    fraction = static_cast<std::size_t>(at - fraction_digits);
    count += fraction;
  }
  if (count == 0) return begin;
  if (count <= 15) {  // the mantissa did not wrap, and a double holds it exactly
    value = static_cast<double>(mantissa) / kPow10[fraction];
    if (negative) value = -value;
    return at;
  }
  const char* first = begin + (*begin == '+' ? 1 : 0);
  const auto result = std::from_chars(first, at, value);
  if (result.ec != std::errc()) value = std::numeric_limits<double>::infinity();
  return at;
}

class LineLexer {
 public:
  LineLexer(std::string_view line, Dialect dialect, Block& block, LexError& error)
      : line_(line), dialect_(dialect), block_(block), error_(error) {}

  bool run() {
    skip_space();
    if (at_end()) return true;
    if (peek() == '%') {  // LinuxCNC and Fanuc program delimiters; Sinumerik %_N_ headers
      block_.percent = true;
      return true;
    }
    if (peek() == '/') ++i_;  // block delete: the switch is off, so the block runs
    while (true) {
      skip_space();
      if (at_end()) return true;
      const char c = peek();
      if (is_alpha(c)) {  // the common case first: a word
        const bool identifier_next = i_ + 1 < line_.size() && is_alpha(line_[i_ + 1]);
        if (!(identifier_next ? identifier() : letter_word())) return false;
      } else if (c == '(') {
        if (!comment()) return false;
      } else if (c == ';') {
        return end_of_block();
      } else if (c == '#' || (c == '$' && dialect_ == Dialect::sinumerik)) {
        return refuse(Refusal::parameter, i_, parameter_end(i_ + 1));
      } else if (c == '[') {
        return refuse(Refusal::expression, i_, bracket_end(i_));
      } else if (c == ':' && dialect_ == Dialect::sinumerik) {
        if (!main_block_number()) return false;
      } else if (c == ',' && dialect_ == Dialect::fanuc) {
        // ,C / ,R: chamfer and corner rounding between blocks (direct drawing).
        return refuse(Refusal::unsupported_word, i_, run_end(i_ + 1));
      } else if (c == '@' || c == '^') {
        return refuse(Refusal::unsupported_word, i_, run_end(i_ + 1));  // LinuxCNC polar words
      } else {
        return refuse(Refusal::malformed, i_, run_end(i_ + 1));
      }
    }
  }

 private:
  bool at_end() const { return i_ >= line_.size(); }
  char peek() const { return line_[i_]; }
  void skip_space() {
    while (!at_end() && is_space(line_[i_])) ++i_;
  }
  std::size_t run_end(std::size_t from) const {
    while (from < line_.size() && !is_space(line_[from])) ++from;
    return from;
  }
  std::size_t identifier_end(std::size_t from) const {
    while (from < line_.size() && is_identifier(line_[from])) ++from;
    return from;
  }
  std::size_t parameter_end(std::size_t from) const {
    if (from < line_.size() && line_[from] == '<') {
      const std::size_t close = line_.find('>', from);
      return close == std::string_view::npos ? line_.size() : close + 1;
    }
    return identifier_end(from);
  }
  std::size_t bracket_end(std::size_t from) const {
    int depth = 0;
    for (std::size_t k = from; k < line_.size(); ++k) {
      if (line_[k] == '[') ++depth;
      if (line_[k] == ']' && --depth == 0) return k + 1;
    }
    return line_.size();
  }

  // The words of the line, begin < end <= its size (no bounds check: the callers found them).
  std::string_view text(std::size_t begin, std::size_t end) const {
    return {line_.data() + begin, end - begin};
  }

  bool refuse(Refusal refusal, std::size_t begin, std::size_t end) {
    error_.refusal = refusal;
    error_.word = {begin + 1, text(begin, end)};
    return false;
  }

  void note_word(std::size_t begin, std::size_t end) {
    if (!block_.has_words) block_.first_word = {begin + 1, text(begin, end)};
    block_.has_words = true;
  }

  // LinuxCNC and Fanuc `( ... )`; Sinumerik has no parenthesis comments (its parentheses belong
  // to expressions and calls, and the control refuses a bare one).
  bool comment() {
    if (dialect_ == Dialect::sinumerik) return refuse(Refusal::malformed, i_, run_end(i_));
    const std::size_t close = line_.find(')', i_ + 1);
    if (close == std::string_view::npos) return refuse(Refusal::malformed, i_, line_.size());
    if (dialect_ == Dialect::linuxcnc) {
      // rs274ngc refuses a nested comment.
      const std::size_t nested = line_.find('(', i_ + 1);
      if (nested < close) return refuse(Refusal::malformed, i_, close + 1);
    }
    i_ = close + 1;
    return true;
  }

  // `;`: a comment to the end of the line in LinuxCNC and Sinumerik; the end of the block on a
  // Fanuc, where text after it would be another block on the same line.
  bool end_of_block() {
    if (dialect_ == Dialect::fanuc) {
      ++i_;
      skip_space();
      if (!at_end()) return refuse(Refusal::malformed, i_, run_end(i_));
    }
    return true;
  }

  // Sinumerik `:10`: a main block number, read like N.
  bool main_block_number() {
    const std::size_t begin = i_++;
    while (!at_end() && is_digit(peek())) ++i_;
    if (i_ == begin + 1) return refuse(Refusal::malformed, begin, run_end(begin));
    note_word(begin, i_);
    return true;
  }

  bool identifier() {
    const std::size_t begin = i_;
    const std::size_t end = identifier_end(i_);
    const std::string_view name = text(begin, end);
    if (dialect_ != Dialect::sinumerik) {
      // Fanuc macro B and LinuxCNC keywords without their O-word; otherwise a letter without
      // its number ("GX").
      if (any_of_upper(name, {"GOTO", "IF", "WHILE", "DO", "END", "THEN"})) {
        return refuse(Refusal::subroutine_or_loop, begin, end);
      }
      if (dialect_ == Dialect::linuxcnc && letter_is_o(begin)) return o_word(begin);
      std::size_t after = end;
      while (after < line_.size() && is_space(line_[after])) ++after;
      if (after < line_.size() && line_[after] == '[') {
        return refuse(Refusal::expression, begin, bracket_end(after));  // SIN[...] and the like
      }
      return refuse(Refusal::malformed, begin, begin + 1);
    }
    return sinumerik_identifier(begin, end, name);
  }

  bool letter_is_o(std::size_t at) const { return ascii_upper(line_[at]) == 'O'; }

  // LinuxCNC o-words (o100 sub, o<name> call, while, if, ...); Fanuc O numbers are read as words.
  bool o_word(std::size_t begin) {
    std::size_t end = begin + 1;
    if (end < line_.size() && line_[end] == '<') {
      end = parameter_end(end);
    } else {
      end = identifier_end(end);
    }
    return refuse(Refusal::subroutine_or_loop, begin, end);
  }

  bool sinumerik_identifier(std::size_t begin, std::size_t end, std::string_view name) {
    std::size_t after = end;
    while (after < line_.size() && is_space(line_[after])) ++after;
    const char next = after < line_.size() ? line_[after] : '\0';
    if (equals_upper(name, "DIAMON") || equals_upper(name, "DIAMOF") ||
        equals_upper(name, "DIAM90")) {
      if (block_.diameter != DiameterWord::none) return refuse(Refusal::malformed, begin, end);
      block_.diameter = equals_upper(name, "DIAMON")   ? DiameterWord::on
                        : equals_upper(name, "DIAMOF") ? DiameterWord::off
                                                       : DiameterWord::diam90;
      note_word(begin, end);
      i_ = end;
      return true;
    }
    if (equals_upper(name, "MSG")) return message(begin, after);
    if (any_of_upper(
            name, {"GOTO",     "GOTOF", "GOTOB",  "GOTOC",   "IF",      "ELSE",  "ENDIF", "WHILE",
                   "ENDWHILE", "FOR",   "ENDFOR", "REPEAT",  "REPEATB", "UNTIL", "LOOP",  "ENDLOOP",
                   "CASE",     "CALL",  "PCALL",  "EXTCALL", "PROC",    "RET"})) {
      return refuse(Refusal::subroutine_or_loop, begin, end);
    }
    if (starts_upper(name, "CYCLE") || starts_upper(name, "POCKET") || starts_upper(name, "SLOT") ||
        starts_upper(name, "HOLES") || equals_upper(name, "LONGHOLE") ||
        equals_upper(name, "MCALL")) {
      return refuse(Refusal::canned_cycle, begin, next == '(' ? close_paren(after) : end);
    }
    if (equals_upper(name, "DEF")) return refuse(Refusal::parameter, begin, line_.size());
    Named which{};
    if (named_word(name, which)) {
      if (next != '=') return refuse(Refusal::malformed, begin, end);
      return named_value(begin, after + 1, which);
    }
    if (next == ':') return refuse(Refusal::subroutine_or_loop, begin, after + 1);  // a label
    if (next == '=') return refuse(Refusal::parameter, begin, end);  // a user variable
    return refuse(Refusal::unsupported_word, begin, end);
  }

  static bool named_word(std::string_view name, Named& which) {
    static constexpr std::array<std::string_view, kNamedCount> kNames = {"LIMS", "ADIS", "ADISPOS",
                                                                         "CR", "TURN"};
    for (std::size_t k = 0; k < kNames.size(); ++k) {
      if (equals_upper(name, kNames[k])) {
        which = static_cast<Named>(k);
        return true;
      }
    }
    return false;
  }

  std::size_t close_paren(std::size_t open) const {
    bool quoted = false;
    for (std::size_t k = open + 1; k < line_.size(); ++k) {
      if (line_[k] == '"') quoted = !quoted;
      if (!quoted && line_[k] == ')') return k + 1;
    }
    return line_.size();
  }

  // MSG("text"): a message on the screen, no time.
  bool message(std::size_t begin, std::size_t open) {
    if (open >= line_.size() || line_[open] != '(') {
      return refuse(Refusal::malformed, begin, open);
    }
    const std::size_t end = close_paren(open);
    if (line_[end - 1] != ')') return refuse(Refusal::malformed, begin, end);
    note_word(begin, end);
    i_ = end;
    return true;
  }

  bool named_value(std::size_t begin, std::size_t value_at, Named which) {
    std::size_t at = value_at;
    while (at < line_.size() && is_space(line_[at])) ++at;
    double value = 0.0;
    std::size_t end = 0;
    if (!word_number(begin, at, value, end)) return false;
    const unsigned bit = 1U << static_cast<unsigned>(which);
    if ((block_.named & bit) != 0) return refuse(Refusal::malformed, begin, end);
    block_.named = static_cast<std::uint8_t>(block_.named | bit);
    block_.named_value[static_cast<std::size_t>(which)] = value;
    block_.named_ref[static_cast<std::size_t>(which)] = {begin + 1, text(begin, end)};
    note_word(begin, end);
    i_ = end;
    return true;
  }

  // The number at `at` of the word that begins at `begin`: its `value` and `end`; false with the
  // word refused when there is none or it is beyond kLargestNumber.
  bool word_number(std::size_t begin, std::size_t at, double& value, std::size_t& end) {
    const char* first = line_.data() + at;
    const char* last = scan(first, line_.data() + line_.size(), value);
    if (last == first) return refuse_value(begin, at);
    end = static_cast<std::size_t>(last - line_.data());
    if (!(std::fabs(value) <= kLargestNumber)) return refuse(Refusal::malformed, begin, end);
    return true;
  }

  // A word whose value is not a number: a parameter, an expression, or nothing.
  bool refuse_value(std::size_t begin, std::size_t at) {
    if (at >= line_.size()) return refuse(Refusal::malformed, begin, at);
    const char c = line_[at];
    if (c == '#' || c == '$') return refuse(Refusal::parameter, begin, parameter_end(at + 1));
    if (c == '[') return refuse(Refusal::expression, begin, bracket_end(at));
    if (c == '(' || c == '-' || c == '+') return refuse(Refusal::expression, begin, run_end(at));
    if (is_alpha(c)) {
      const std::size_t end = identifier_end(at);
      if (dialect_ == Dialect::sinumerik) {
        // X=R1, X=MYVAR: variables; X=AC(...), X=IC(...), SIN(...): expressions.
        const bool call = end < line_.size() && line_[end] == '(';
        return refuse(call ? Refusal::expression : Refusal::parameter, begin,
                      call ? close_paren(end) : end);
      }
      std::size_t after = end;
      while (after < line_.size() && is_space(line_[after])) ++after;
      if (after < line_.size() && line_[after] == '[') {
        return refuse(Refusal::expression, begin, bracket_end(after));
      }
    }
    return refuse(Refusal::malformed, begin, begin + 1);  // a letter without its number
  }

  bool letter_word() {
    const std::size_t begin = i_;
    const char letter = ascii_upper(peek());
    if (letter == 'O' && dialect_ == Dialect::linuxcnc) return o_word(begin);
    if (dialect_ == Dialect::sinumerik) {
      if (letter == 'R') return refuse(Refusal::parameter, begin, identifier_end(begin + 1));
      if (letter == 'L') return refuse(Refusal::subroutine_or_loop, begin, run_end(begin));
    }
    std::size_t at = begin + 1;
    while (at < line_.size() && is_space(line_[at])) ++at;
    if (dialect_ == Dialect::sinumerik && at < line_.size() && line_[at] == '=') {
      ++at;
      while (at < line_.size() && is_space(line_[at])) ++at;
      if (at < line_.size() && line_[at] == '"' && letter == 'T') return tool_name(begin, at);
    }
    double value = 0.0;
    std::size_t end = 0;
    if (!word_number(begin, at, value, end)) return false;
    const WordRef ref{begin + 1, text(begin, end)};
    i_ = end;
    note_word(begin, end);
    if (letter == 'G' || letter == 'M') return code_word(letter, line_[at], value, ref);
    const std::size_t index = letter_index(letter);
    if (block_.has(letter)) return refuse(Refusal::malformed, begin, end);  // a word twice
    block_.letters |= letter_bit(letter);
    block_.value[index] = value;
    block_.ref[index] = ref;
    return true;
  }

  // Sinumerik T="name": a tool by name; read as a T word.
  bool tool_name(std::size_t begin, std::size_t quote) {
    const std::size_t close = line_.find('"', quote + 1);
    if (close == std::string_view::npos) return refuse(Refusal::malformed, begin, line_.size());
    const std::size_t end = close + 1;
    if (block_.has('T')) return refuse(Refusal::malformed, begin, end);
    block_.letters |= letter_bit('T');
    block_.value[letter_index('T')] = 1.0;
    block_.ref[letter_index('T')] = {begin + 1, text(begin, end)};
    note_word(begin, end);
    i_ = end;
    return true;
  }

  // G and M numbers: at most one decimal digit (G61.1), never signed.
  bool code_word(char letter, char sign, double number, const WordRef& ref) {
    const std::size_t begin = ref.column - 1;
    const std::size_t end = begin + ref.text.size();
    if (sign == '-' || sign == '+') return refuse(Refusal::malformed, begin, end);
    if (!(number < 1e5)) return refuse(Refusal::unsupported_word, begin, end);
    const int tenths = static_cast<int>(number * 10.0 + 0.5);
    if (std::fabs(tenths - number * 10.0) > 1e-6) {
      return refuse(Refusal::unsupported_word, begin, end);  // G1.23: no such code
    }
    const CodeWord word{tenths, ref};
    if (letter == 'G') {
      if (block_.g_count == Block::kMaxCodes) return refuse(Refusal::malformed, begin, end);
      block_.g[block_.g_count++] = word;
    } else {
      if (block_.m_count == Block::kMaxCodes) return refuse(Refusal::malformed, begin, end);
      block_.m[block_.m_count++] = word;
    }
    return true;
  }

  std::string_view line_;
  Dialect dialect_;
  Block& block_;
  LexError& error_;
  std::size_t i_ = 0;
};

}  // namespace

const char* scan_number(const char* begin, const char* end, double& value) {
  return scan(begin, end, value);
}

bool lex_line(std::string_view line, program::Dialect dialect, Block& block, LexError& error) {
  block.clear();
  return LineLexer(line, dialect, block, error).run();
}

}  // namespace cutcalc::domain::machine_time::detail
