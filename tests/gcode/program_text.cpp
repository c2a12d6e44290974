#include "gcode/program_text.h"

#include <cctype>
#include <cstdlib>
#include <sstream>

namespace cutcalc::test::gcode {
namespace {

std::vector<std::string> lines_of(std::string_view text) {
  std::vector<std::string> lines;
  std::string line;
  std::istringstream in{std::string(text)};
  while (std::getline(in, line)) lines.push_back(line);
  return lines;
}

// "G01" -> "G1", "M03" -> "M3"; other words unchanged.
std::string short_word(const std::string& word) {
  if (word.size() == 3 && (word[0] == 'G' || word[0] == 'M') && word[1] == '0' &&
      std::isdigit(static_cast<unsigned char>(word[2])) != 0) {
    std::string out(1, word[0]);
    out.push_back(word[2]);
    return out;
  }
  return word;
}

std::string without_comment(const std::string& line, std::string_view dialect) {
  if (dialect == "sinumerik") return line.substr(0, line.find(';'));
  std::string out;
  bool inside = false;
  for (const char c : line) {
    if (c == '(') inside = true;
    if (!inside) out.push_back(c);
    if (c == ')') inside = false;
  }
  return out;
}

}  // namespace

std::string translate_to_linuxcnc(std::string_view program, std::string_view dialect) {
  if (dialect == "linuxcnc") return std::string(program);
  std::string out;
  for (const std::string& line : lines_of(program)) {
    if (dialect == "fanuc") {
      if (!line.empty() && line[0] == 'O') continue;
      if (!line.empty() && line[0] == '(') {
        out.append(line).append("\n");
        continue;
      }
      std::istringstream words(line);
      std::string word;
      std::string translated;
      while (words >> word) {
        if (!translated.empty()) translated.push_back(' ');
        translated.append(short_word(word));
      }
      out.append(translated).append("\n");
      continue;
    }
    // sinumerik
    if (!line.empty() && line[0] == ';') {
      out.append("(").append(line.substr(std::min<std::size_t>(2, line.size()))).append(")\n");
      continue;
    }
    if (line == "D1" || line == "D0") continue;
    std::istringstream words(line);
    std::string word;
    std::string translated;
    while (words >> word) {
      if (word == "G710") word = "G21";
      if (word == "G700") word = "G20";
      if (!translated.empty()) translated.push_back(' ');
      translated.append(word);
    }
    out.append(translated).append("\n");
  }
  return out;
}

std::vector<std::vector<std::string>> words_of(std::string_view program, std::string_view dialect) {
  std::vector<std::vector<std::string>> blocks;
  for (const std::string& line : lines_of(program)) {
    std::istringstream words(without_comment(line, dialect));
    std::vector<std::string> block;
    std::string word;
    while (words >> word) block.push_back(word);
    if (!block.empty()) blocks.push_back(block);
  }
  return blocks;
}

std::vector<TextMove> moves_of(std::string_view program) {
  std::vector<TextMove> moves;
  double x = 0, y = 0, z = 0, f = 0;
  int motion = -1;
  for (const auto& block : words_of(program, "linuxcnc")) {
    bool moved = false;
    const double from_x = x, from_y = y, from_z = z;
    for (const std::string& word : block) {
      const double value = std::strtod(word.c_str() + 1, nullptr);
      switch (word[0]) {
        case 'G':
          if (word == "G0" || word == "G1") motion = word == "G1" ? 1 : 0;
          break;
        case 'X':
          x = value;
          moved = true;
          break;
        case 'Y':
          y = value;
          moved = true;
          break;
        case 'Z':
          z = value;
          moved = true;
          break;
        case 'F':
          f = value;
          break;
        default:
          break;
      }
    }
    if (moved && motion >= 0) moves.push_back({motion == 1, x, y, z, from_x, from_y, from_z, f});
  }
  return moves;
}

}  // namespace cutcalc::test::gcode
