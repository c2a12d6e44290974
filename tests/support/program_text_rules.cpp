#include "support/program_text_rules.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>
#include <regex>
#include <sstream>
#include <vector>

namespace cutcalc::testing {
namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) lines.push_back(line);
  return lines;
}

}  // namespace

void expect_text_rules(const std::string& program, const std::string& dialect) {
  SCOPED_TRACE(dialect + " program:\n" + program);
  const auto lines = lines_of(program);
  ASSERT_GE(lines.size(), 8U);
  EXPECT_EQ(program.back(), '\n');
  EXPECT_TRUE(std::all_of(program.begin(), program.end(),
                          [](char c) { return c == '\n' || (c >= 0x20 && c < 0x7f); }));
  const std::regex minus_zero(R"([A-Z]-0(\.0+)?( |$))");
  const std::regex real_without_point(R"(\b[XYZIJCF]-?[0-9]+( |$))");
  const std::regex m_word(R"((^| )M[0-9]+)");
  const bool semicolon_comments = dialect == "sinumerik";
  std::size_t o_words = 0;
  for (const std::string& line : lines) {
    const bool comment = semicolon_comments ? line.rfind(';', 0) == 0 : line.rfind('(', 0) == 0;
    if (comment) {
      if (dialect == "fanuc") {
        EXPECT_EQ(line.find_first_of("abcdefghijklmnopqrstuvwxyz"), std::string::npos)
            << "fanuc comments are upper case: " << line;
      }
      const std::string text =
          semicolon_comments ? line.substr(1) : line.substr(1, line.size() - 2);
      EXPECT_EQ(text.find_first_of("();%"), std::string::npos) << line;
      continue;
    }
    if (line == "%") continue;
    if (line.rfind('O', 0) == 0) ++o_words;
    EXPECT_FALSE(std::regex_search(line, minus_zero)) << "-0 in " << line;
    EXPECT_FALSE(std::regex_search(line, real_without_point)) << "no decimal point in " << line;
    const auto m_words = std::distance(std::sregex_iterator(line.begin(), line.end(), m_word),
                                       std::sregex_iterator());
    EXPECT_LE(m_words, 1) << "more than one M word in " << line;
    EXPECT_EQ(line.find_first_of("abcdefghijklmnopqrstuvwxyz,"), std::string::npos) << line;
  }
  if (dialect == "fanuc") {
    EXPECT_EQ(lines[0], "%");
    EXPECT_TRUE(std::regex_match(lines[1], std::regex(R"(O[0-9]{4} \([A-Z][A-Z0-9_]*\))")))
        << lines[1];
    EXPECT_EQ(o_words, 1U);
    const auto units = std::find_if(lines.begin(), lines.end(),
                                    [](const std::string& l) { return l.rfind('G', 0) == 0; });
    ASSERT_NE(units, lines.end());
    EXPECT_TRUE(*units == "G21" || *units == "G20") << "the units alone, first: " << *units;
    if (program.find(" M03\n") != std::string::npos) {  // milling `S{n} M03`, lathe `G9x S{n} M03`
      EXPECT_TRUE(std::regex_search(program, std::regex(R"(\n(G9[67] )?S[0-9]+ M03\n)")))
          << "integer S";
    }
    if (program.find("\nG50 ") != std::string::npos) {  // the lathe spindle limit
      EXPECT_TRUE(std::regex_search(program, std::regex(R"(\nG50 S[0-9]+\n)"))) << "integer G50 S";
    }
    std::string code;  // the blocks, without the comment lines
    for (const std::string& line : lines) {
      if (line.rfind('(', 0) != 0) code += line + "\n";
    }
    EXPECT_FALSE(std::regex_search(code, std::regex(R"((^|[ \n])[GM][0-9]( |\n))")))
        << "one-digit G or M word";
    EXPECT_EQ(lines[lines.size() - 2], "M30");
    EXPECT_EQ(lines.back(), "%");
  } else if (dialect == "sinumerik") {
    EXPECT_TRUE(lines[0].rfind("; ", 0) == 0);
    EXPECT_TRUE(program.find("G710") != std::string::npos ||
                program.find("G700") != std::string::npos);
    EXPECT_EQ(program.find_first_of("%()"), std::string::npos);
    EXPECT_EQ(lines.back(), "M30");
  } else {
    EXPECT_EQ(lines[0], "%");
    EXPECT_EQ(lines[lines.size() - 2], "M30");
    EXPECT_EQ(lines.back(), "%");
  }
}

}  // namespace cutcalc::testing
