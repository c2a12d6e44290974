#pragma once
// Request builders, a program-text parser and small geometry helpers shared by the polygon-hole
// tests (spec shared/domain/polygon-holes.md).

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "domain/polygon/polygon_hole.h"

namespace cutcalc::test::polygon {

using domain::polygon::PolygonHoleParams;
using domain::polygon::PolygonHoleResult;
using domain::polygon::Synchronization;

inline constexpr double kPi = std::numbers::pi;

// d = 20 (or the given d), 1 um fit, depth 0.2 in steps of 0.1, 30 rpm, defaults otherwise.
inline PolygonHoleParams hole(int N, double d = 20.0, double tolerance_mm = 0.001,
                              Synchronization synchronization = Synchronization::feed_per_rev) {
  PolygonHoleParams p;
  p.faces = N;
  p.inscribed_diameter_mm = d;
  p.depth_mm = 0.2;
  p.step_down_mm = 0.1;
  p.spindle_speed_rpm = 30.0;
  p.tolerance_mm = tolerance_mm;
  p.synchronization = synchronization;
  return p;
}

// The paper's square a = 16 (N = 4, d = 16) of spec section 12.
inline PolygonHoleParams square_a16(
    Synchronization synchronization = Synchronization::feed_per_rev) {
  return hole(4, 16.0, 0.001, synchronization);
}

inline PolygonHoleResult generate(const PolygonHoleParams& params) {
  const auto result = domain::polygon::generate_polygon_hole(params);
  EXPECT_TRUE(result.ok()) << "N " << params.faces << " d " << params.inscribed_diameter_mm
                           << " tol " << params.tolerance_mm << ": "
                           << (result.ok() ? "" : result.error().detail);
  return result.ok() ? result.value() : PolygonHoleResult{};
}

// One program line split into words: letter and the text after it ("G3", "X-0.2709").
struct Word {
  char letter = ' ';
  std::string value;
  [[nodiscard]] double number() const { return std::strtod(value.c_str(), nullptr); }
};

struct Line {
  std::string text;
  bool comment = false;
  std::vector<Word> words;

  [[nodiscard]] std::optional<Word> find(char letter) const {
    for (const Word& word : words) {
      if (word.letter == letter) {
        return word;
      }
    }
    return std::nullopt;
  }
  [[nodiscard]] bool is_arc() const {
    return !words.empty() && words[0].letter == 'G' &&
           (words[0].value == "2" || words[0].value == "3");
  }
  [[nodiscard]] bool has(char letter) const { return find(letter).has_value(); }
};

// Splits the program into lines (without the LF) and the non-comment lines into words.
inline std::vector<Line> parse_program(const std::string& program) {
  std::vector<Line> lines;
  std::size_t begin = 0;
  while (begin < program.size()) {
    std::size_t end = program.find('\n', begin);
    if (end == std::string::npos) {
      end = program.size();
    }
    Line line;
    line.text = program.substr(begin, end - begin);
    line.comment = !line.text.empty() && line.text.front() == '(';
    if (!line.comment && line.text != "%") {
      std::istringstream in(line.text);
      std::string token;
      while (in >> token) {
        line.words.push_back(Word{token.front(), token.substr(1)});
      }
    }
    lines.push_back(std::move(line));
    begin = end + 1;
  }
  return lines;
}

inline std::vector<Line> arc_lines(const std::vector<Line>& lines) {
  std::vector<Line> arcs;
  for (const Line& line : lines) {
    if (line.is_arc()) {
      arcs.push_back(line);
    }
  }
  return arcs;
}

// P23 recomputed from the printed arcs alone: each IJ arc from its printed start S and end E,
// centre S + (I, J), length |sweep| (|S-C| + |E-C|) / 2, sweep 2 pi when E = S.
inline double printed_length(const std::vector<Line>& arcs, std::size_t first, std::size_t count,
                             double start_x, double start_y) {
  double length = 0.0;
  double sx = start_x;
  double sy = start_y;
  for (std::size_t b = first; b < first + count; ++b) {
    const double ex = arcs[b].find('X')->number();
    const double ey = arcs[b].find('Y')->number();
    const double cx = sx + arcs[b].find('I')->number();
    const double cy = sy + arcs[b].find('J')->number();
    double sweep = 2.0 * kPi;
    if (ex != sx || ey != sy) {
      sweep = std::atan2(ey - cy, ex - cx) - std::atan2(sy - cy, sx - cx);
      while (sweep <= 0.0) {
        sweep += 2.0 * kPi;
      }
    }
    length += sweep * 0.5 * (std::hypot(sx - cx, sy - cy) + std::hypot(ex - cx, ey - cy));
    sx = ex;
    sy = ey;
  }
  return length;
}

// printf("%.4f") with -0.0000 written 0.0000 (section 5), for expectations.
inline std::string four_decimals(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.4f", value);
  std::string text(buffer);
  return text == "-0.0000" ? "0.0000" : text;
}

}  // namespace cutcalc::test::polygon
