// The program text, spec polygon-holes.md section 5 (P22, P23): text rules, skeleton, F lines,
// layers and helical ramps, loop length from the printed numbers, C words, warning comments and
// the file name.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "domain/polygon/gcode_writer.h"
#include "polygon_test_support.h"

namespace {

namespace polygon_detail = cutcalc::domain::polygon::detail;
using cutcalc::domain::polygon::program_text;
using cutcalc::test::polygon::arc_lines;
using cutcalc::test::polygon::four_decimals;
using cutcalc::test::polygon::generate;
using cutcalc::test::polygon::hole;
using cutcalc::test::polygon::kPi;
using cutcalc::test::polygon::Line;
using cutcalc::test::polygon::parse_program;
using cutcalc::test::polygon::PolygonHoleParams;
using cutcalc::test::polygon::printed_length;
using cutcalc::test::polygon::square_a16;
using cutcalc::test::polygon::Synchronization;

int word_rank(char letter) {
  const std::string order = "GXYZIJCFSM";
  const auto at = order.find(letter);
  return at == std::string::npos ? -1 : static_cast<int>(at);
}

// Section 5 text rules on one program.
void expect_text_rules(const std::string& program) {
  ASSERT_FALSE(program.empty());
  EXPECT_EQ(program.back(), '\n');
  for (const char c : program) {
    const auto byte = static_cast<unsigned char>(c);
    EXPECT_TRUE(c == '\n' || (byte >= 0x20 && byte < 0x7f)) << "byte " << int{byte};
  }
  EXPECT_EQ(program.find(','), std::string::npos);
  EXPECT_EQ(program.find('\r'), std::string::npos);
  const std::vector<Line> lines = parse_program(program);
  ASSERT_GE(lines.size(), 3U);
  EXPECT_EQ(lines.front().text, "%");
  EXPECT_EQ(lines.back().text, "%");
  EXPECT_EQ(std::count(program.begin(), program.end(), '%'), 2);
  EXPECT_EQ(lines[1].text.rfind("(CUTCALC POLYGON HOLE N", 0), 0U);
  for (std::size_t i = 1; i + 1 < lines.size(); ++i) {
    const Line& line = lines[i];
    EXPECT_LT(line.text.size(), 200U);  // rs274 refuses lines near 255 characters
    if (line.comment) {
      EXPECT_EQ(line.text.back(), ')') << line.text;
      EXPECT_EQ(std::count(line.text.begin(), line.text.end(), '('), 1) << line.text;
      EXPECT_EQ(std::count(line.text.begin(), line.text.end(), ')'), 1) << line.text;
      continue;
    }
    ASSERT_FALSE(line.words.empty()) << "empty line " << i;
    int rank = 0;
    for (const auto& word : line.words) {
      EXPECT_TRUE(std::isupper(static_cast<unsigned char>(word.letter))) << line.text;
      EXPECT_GE(word_rank(word.letter), rank) << "word order: " << line.text;
      rank = std::max(rank, word_rank(word.letter));
      if (word.letter == 'G' || word.letter == 'M') {
        EXPECT_EQ(word.value.find('.'), std::string::npos) << line.text;
        continue;
      }
      // Every real number as printf("%.4f"), never -0.0000.
      const auto point = word.value.find('.');
      ASSERT_NE(point, std::string::npos) << line.text;
      EXPECT_EQ(word.value.size() - point, 5U) << line.text;
      EXPECT_NE(word.value, "-0.0000") << line.text;
      EXPECT_EQ(four_decimals(word.number()), word.value) << line.text;
    }
  }
}

TEST(GcodeText, TextRulesForEveryNAndMode) {
  for (int N = 3; N <= 12; ++N) {
    for (const auto sync : {Synchronization::feed_per_rev, Synchronization::c_axis}) {
      SCOPED_TRACE(testing::Message()
                   << "N " << N << " c_axis " << (sync == Synchronization::c_axis));
      PolygonHoleParams params = hole(N, 20.0, 0.001, sync);
      params.loops_per_layer = N % 3 == 0 ? 1 : N - 1;
      params.block_time_ms = 8.0;  // both warnings in feed_per_rev mode for some N
      params.spindle_speed_rpm = 400.0;
      const auto result = generate(params);
      expect_text_rules(program_text(result));
      expect_text_rules(program_text(result, true));
    }
  }
  // Small and odd inputs: d = 1, 0.1 um, deep holes with an uneven step.
  PolygonHoleParams small = hole(3, 1.0, 0.0001);
  small.depth_mm = 1.0;
  small.step_down_mm = 0.3;
  expect_text_rules(program_text(generate(small)));
}

TEST(GcodeText, NumberFormat) {
  const auto plain = [](double value) {
    return cutcalc::domain::program::format_fixed(value, polygon_detail::kPlainDecimals);
  };
  EXPECT_EQ(plain(-0.00004), "0.0000");
  EXPECT_EQ(plain(-0.0), "0.0000");
  EXPECT_EQ(plain(-0.00005001), "-0.0001");
  EXPECT_EQ(plain(300.0), "300.0000");
  EXPECT_EQ(plain(-0.27094), "-0.2709");
  EXPECT_EQ(plain(1.23760430703), "1.2376");
  EXPECT_EQ(plain(24.02466280517), "24.0247");
  for (const double x : {0.00005, 0.00015, 2.5e-5, 1.99995, -7.77775, 123456.78905}) {
    EXPECT_EQ(plain(x),
              four_decimals(x)) << x;  // the same rounding as printf
  }
}

// Section 5 skeleton, feed_per_rev: the line sequence around the loops.
TEST(GcodeText, SkeletonFeedPerRev) {
  const auto result = generate(square_a16());
  const std::vector<Line> lines = parse_program(program_text(result));
  EXPECT_EQ(lines[1].text, "(CUTCALC POLYGON HOLE N4 D16.0000 A16.0000)");
  std::vector<std::string> code;
  for (const Line& line : lines) {
    if (!line.comment && !line.is_arc()) {
      code.push_back(line.text);
    }
  }
  const std::vector<std::string> want{"%",
                                      "G21 G17 G90 G40 G80 G94",
                                      "G0 Z5.0000",
                                      "S30.0000 M3",
                                      "G0 X0.0000 Y1.2376",
                                      "G95 F24.0265",
                                      "G1 Z0.0000",
                                      "G95 F24.0247",
                                      "G95 F24.0265",
                                      "G95 F24.0247",
                                      "G0 Z5.0000",
                                      "G94",
                                      "M5",
                                      "M30",
                                      "%"};
  EXPECT_EQ(code, want);
  // The first arc of the paper's square (its X-0.2709 example) with I, J from the unrounded
  // centre and start.
  const auto arcs = arc_lines(lines);
  EXPECT_EQ(arcs.front().text, "G3 X-0.2709 Y1.2200 Z-0.0034 I0.0000 J-2.0974");
  EXPECT_EQ(arcs.back().text.substr(0, 22), "G3 X0.0000 Y1.2376 I-0");
  EXPECT_EQ(result.file_name, "polygon-hole-N4-d16.0000.ngc");
}

// Section 5 skeleton, c_axis: no S/M3, C0 at the start, one G94 F line, a C word on every arc.
TEST(GcodeText, SkeletonCAxis) {
  const auto result = generate(square_a16(Synchronization::c_axis));
  const std::vector<Line> lines = parse_program(program_text(result));
  std::vector<std::string> code;
  for (const Line& line : lines) {
    if (!line.comment && !line.is_arc()) {
      code.push_back(line.text);
    }
  }
  const std::vector<std::string> want{"%",
                                      "G21 G17 G90 G40 G80 G94",
                                      "G0 Z5.0000",
                                      "G0 X0.0000 Y1.2376 C0.0000",
                                      "G94 F720.7399",
                                      "G1 Z0.0000",
                                      "G0 Z5.0000",
                                      "M30",
                                      "%"};
  EXPECT_EQ(code, want);
  const auto arcs = arc_lines(lines);
  ASSERT_EQ(arcs.size(), 150U);
  // C = -(180/pi) t_end, cumulative: every loop turns the rotor 360/(N-1) = 120 deg; the C words
  // decrease along the program, and the last is -720.
  double previous = 0.0;
  for (std::size_t b = 0; b < arcs.size(); ++b) {
    ASSERT_TRUE(arcs[b].has('C'));
    const double C = arcs[b].find('C')->number();
    EXPECT_LT(C, previous);
    previous = C;
    if (b >= 25) {
      EXPECT_NEAR(C - arcs[b - 25].find('C')->number(), -120.0, 1.5e-4);
    }
  }
  EXPECT_EQ(arcs.back().find('C')->value, "-720.0000");
  EXPECT_EQ(arcs[24].find('C')->value, "-120.0000");
}

// P22: n = ceil(depth / step - 1e-9) equal layers; the first loop of a layer ramps with Z linear
// in path length, the others are flat; loops_per_layer = 1 adds one flat loop at the bottom.
TEST(GcodeText, LayersAndHelicalRamps) {
  struct Case {
    double depth, step;
    int loops_per_layer;
    int layers;
  };
  for (const Case& c : {Case{0.2, 0.1, 3, 2}, Case{0.25, 0.1, 1, 3}, Case{0.3, 0.1, 2, 3},
                        Case{0.1, 0.5, 4, 1}, Case{1.0, 0.3, 1, 4}}) {
    SCOPED_TRACE(testing::Message() << "depth " << c.depth << " step " << c.step);
    PolygonHoleParams params = hole(5, 20.0, 0.001);
    params.depth_mm = c.depth;
    params.step_down_mm = c.step;
    params.loops_per_layer = c.loops_per_layer;
    const auto result = generate(params);
    const auto arcs = arc_lines(parse_program(program_text(result)));
    const auto per_loop = static_cast<std::size_t>(result.blocks_per_loop);
    const int loops = c.layers * c.loops_per_layer + (c.loops_per_layer == 1 ? 1 : 0);
    ASSERT_EQ(arcs.size(), static_cast<std::size_t>(loops) * per_loop);
    const double dz = c.depth / c.layers;
    for (int loop = 0; loop < loops; ++loop) {
      const bool ramp = loop < c.layers * c.loops_per_layer && loop % c.loops_per_layer == 0;
      const int layer = std::min(loop / c.loops_per_layer + 1, c.layers);
      double s = 0.0;
      for (std::size_t b = 0; b < per_loop; ++b) {
        const Line& arc = arcs[static_cast<std::size_t>(loop) * per_loop + b];
        EXPECT_EQ(arc.has('Z'), ramp);
        if (!ramp) {
          continue;
        }
        s = printed_length(arcs, static_cast<std::size_t>(loop) * per_loop, b + 1, 0.0,
                           std::stod(four_decimals(result.eccentricity_mm)));
        const double want = -(layer - 1) * dz - dz * s / result.loop_length_mm;
        EXPECT_NEAR(arc.find('Z')->number(), want, 1e-4);
        if (b + 1 == per_loop) {
          EXPECT_EQ(arc.find('Z')->value, four_decimals(-layer * dz));
        }
      }
    }
  }
}

// P23: loop_length_mm from the printed numbers as LinuxCNC interpolates them; feed_per_rev =
// (N-1) L_p; G95 F words for flat loops and ramp loops (with the helix root); F lines before
// every ramp loop and on every change.
TEST(GcodeText, PrintedLoopLengthAndFeedWords) {
  for (int N = 3; N <= 12; ++N) {
    SCOPED_TRACE(N);
    PolygonHoleParams params = hole(N, 20.0, 0.0005);
    params.loops_per_layer = N == 5 ? 1 : 2;
    const auto result = generate(params);
    const auto lines = parse_program(program_text(result));
    const auto arcs = arc_lines(lines);
    const double e_printed = std::stod(four_decimals(result.eccentricity_mm));
    const double L_p =
        printed_length(arcs, 0, static_cast<std::size_t>(result.blocks_per_loop), 0.0, e_printed);
    EXPECT_NEAR(result.loop_length_mm, L_p, 1e-12);
    EXPECT_NEAR(result.feed_per_rev_mm, (N - 1) * L_p, 1e-12);
    // |L_p - L| <= 2 pi tol + rounding
    const polygon_detail::PolygonShape shape = polygon_detail::make_polygon_shape(N, 20.0);
    EXPECT_LE(std::abs(L_p - polygon_detail::CentrePath(shape).loop_length()),
              2.0 * kPi * params.tolerance_mm + 1e-3);
    const double dz = 0.1;
    const std::string flat = four_decimals(result.feed_per_rev_mm);
    const std::string ramp =
        four_decimals(result.feed_per_rev_mm * std::sqrt(1.0 + (dz / L_p) * (dz / L_p)));
    std::string feed;
    bool feed_line_since_last_arc = false;
    bool previous_arc_ramp = false;
    for (const Line& line : lines) {
      if (line.comment || line.words.empty()) {
        continue;
      }
      if (line.words[0].value == "95") {
        feed = line.find('F')->value;
        feed_line_since_last_arc = true;
      }
      if (line.is_arc()) {
        EXPECT_EQ(feed, line.has('Z') ? ramp : flat) << line.text;
        if (line.has('Z') != previous_arc_ramp) {
          EXPECT_TRUE(feed_line_since_last_arc) << "F line missing before " << line.text;
        }
        previous_arc_ramp = line.has('Z');
        feed_line_since_last_arc = false;
      }
    }
  }
}

// I, J are the unrounded centre minus the unrounded start (normative): compare with the blocks.
TEST(GcodeText, CentreOffsetsFromUnroundedPoints) {
  const polygon_detail::PolygonShape shape = polygon_detail::make_polygon_shape(4, 1.0);
  const polygon_detail::CentrePath path(shape);
  const auto fit = polygon_detail::fit_ellipse_arc(path, 0.005 / 16.0);
  ASSERT_TRUE(fit.ok());
  const auto blocks = polygon_detail::loop_blocks(path, fit.value(), 1e-9);
  const polygon_detail::PrintedLoop loop = polygon_detail::print_loop(blocks, 16.0);
  ASSERT_EQ(loop.blocks.size(), blocks.size());
  Eigen::Vector2d start(0.0, 16.0 * shape.e);
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const Eigen::Vector2d centre = 16.0 * blocks[b].arc.centre;
    EXPECT_EQ(loop.blocks[b].I, four_decimals(centre.x() - start.x()));
    EXPECT_EQ(loop.blocks[b].J, four_decimals(centre.y() - start.y()));
    start = 16.0 * blocks[b].arc.end;
    EXPECT_EQ(loop.blocks[b].X, four_decimals(start.x()));
    EXPECT_EQ(loop.blocks[b].Y, four_decimals(start.y()));
  }
  // The reference value of square_a16_tol5um needs exactly this rule.
  EXPECT_NEAR(loop.printed_length, 8.00933421639, 1e-10);
}

TEST(GcodeText, WarningCommentsFollowTheFirstCommentLine) {
  PolygonHoleParams params = hole(6, 20.0, 0.001);
  params.spindle_speed_rpm = 1000.0;
  const auto result = generate(params);
  ASSERT_EQ(result.warnings.size(), 2U);
  const std::string text = program_text(result, true);
  const auto lines = parse_program(text);
  EXPECT_EQ(lines[1].text, "(CUTCALC POLYGON HOLE N6 D20.0000 A11.5470)");
  for (std::size_t i = 0; i < 2; ++i) {
    const std::string start =
        "(WARNING " + std::string(cutcalc::domain::program::warning_name(result.warnings[i].code));
    EXPECT_EQ(lines[2 + i].text.rfind(start + ": ", 0), 0U);
  }
  EXPECT_EQ(text.size(),
            program_text(result).size() + lines[2].text.size() + lines[3].text.size() + 2);
  // Without warnings the program is unchanged.
  auto quiet = generate(hole(6, 20.0, 0.001, Synchronization::c_axis));
  ASSERT_TRUE(quiet.warnings.empty());
  EXPECT_EQ(program_text(quiet, true), program_text(quiet));
  EXPECT_EQ(result.file_name, "polygon-hole-N6-d20.0000.ngc");
}

}  // namespace
