#include "gcode/program_text.h"

#include <algorithm>
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

std::vector<std::string> words_in(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> words;
  std::string word;
  while (in >> word) words.push_back(word);
  return words;
}

std::string joined(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& word : words) {
    if (!out.empty()) out.push_back(' ');
    out.append(word);
  }
  return out;
}

bool contains(const std::vector<std::string>& words, std::string_view word) {
  return std::find(words.begin(), words.end(), word) != words.end();
}

// A word from its letter and number (not `"P" + rest`: GCC 12 warns -Wrestrict on it).
std::string with_letter(char letter, std::string_view number) {
  std::string word(1, letter);
  word.append(number);
  return word;
}

// fanuc lathe `T0707`: tool 07 with offset 07 (a milling T word has no offset digits).
bool is_turret_tool_word(const std::string& word) {
  return word.size() == 5 && word[0] == 'T' &&
         std::all_of(word.begin() + 1, word.end(),
                     [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; });
}

}  // namespace

std::string translate_to_linuxcnc(std::string_view program, std::string_view dialect) {
  if (dialect == "linuxcnc") return std::string(program);
  std::string out;
  std::string lathe_clamp;  // fanuc `G50 S{m}`, waiting for its G96 block
  for (const std::string& line : lines_of(program)) {
    if (dialect == "fanuc") {
      if (!line.empty() && line[0] == 'O') continue;
      if (!line.empty() && line[0] == '(') {
        out.append(line).append("\n");
        continue;
      }
      std::vector<std::string> block = words_in(line);
      for (std::string& word : block) word = short_word(word);
      if (block.size() == 2 && block[0] == "G50" && block[1][0] == 'S') {
        lathe_clamp = block[1].substr(1);  // into the next G96 block as D
        continue;
      }
      std::vector<std::string> translated;
      const bool dwell = contains(block, "G4");
      for (const std::string& word : block) {
        if (word == "G99") {  // lathe feed per revolution; X words are diameters (G7)
          translated.emplace_back("G7");
          translated.emplace_back("G95");
        } else if (dwell && word[0] == 'X') {
          translated.push_back(with_letter('P', word.substr(1)));
        } else if (is_turret_tool_word(word)) {
          translated.push_back(with_letter('T', std::to_string(std::stoi(word.substr(1, 2)))));
          translated.emplace_back("M6");
          translated.emplace_back("G43");
        } else if (word == "G96" && !lathe_clamp.empty()) {
          translated.push_back(word);
          translated.push_back(with_letter('D', lathe_clamp));
          lathe_clamp.clear();
        } else {
          translated.push_back(word);
        }
      }
      out.append(joined(translated)).append("\n");
      continue;
    }
    // sinumerik
    if (!line.empty() && line[0] == ';') {
      out.append("(").append(line.substr(std::min<std::size_t>(2, line.size()))).append(")\n");
      continue;
    }
    if (line == "D1" || line == "D0") continue;
    const std::vector<std::string> block = words_in(line);
    const bool dwell = contains(block, "G4");
    const bool tool_call = !block.empty() && block[0][0] == 'T';
    std::vector<std::string> translated;
    for (const std::string& word : block) {
      if (word == "G710") {
        translated.emplace_back("G21");
      } else if (word == "G700") {
        translated.emplace_back("G20");
      } else if (word == "DIAMON") {
        translated.emplace_back("G7");
      } else if (word.rfind("LIMS=", 0) == 0) {
        translated.push_back(with_letter('D', word.substr(5)));
      } else if (dwell && word[0] == 'F') {
        translated.push_back(with_letter('P', word.substr(1)));
      } else if (tool_call && word == "D1") {  // lathe `T7 D1`: the tool and its offset
        translated.emplace_back("M6");
        translated.emplace_back("G43");
      } else {
        translated.push_back(word);
      }
    }
    out.append(joined(translated)).append("\n");
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
