// The flat's program (lathe-flat.md section 6, F22): the block sequence of 6.2 (flats outer,
// layers inner), the words of every block from the test's own closed forms, F in every G93 block,
// inch conversion of X and the approach F only, the comment lines and an F that prints as zero.

#include "domain/lathe_flat/flat_program.h"
#include "domain/lathe_flat/lathe_flat_settings.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace cutcalc::domain::lathe_flat {
namespace {

using program::Dialect;
using program::ProgramOptions;
using program::Units;

using settings::paper_flat;

Result<FlatProgram> written(const LatheFlatParams& p, const ProgramOptions& options) {
  const auto flat = compute_lathe_flat(p);
  if (!flat.ok()) return flat.error();
  return write_flat_program(p, flat.value(), options);
}

std::string program_of(const LatheFlatParams& p, const ProgramOptions& options = {}) {
  const auto out = written(p, options);
  EXPECT_TRUE(out.ok()) << (out.ok() ? "" : error_code_name(out.error().code));
  return out.ok() ? program_text(out.value()) : std::string{};
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string fixed(double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

// The whole expected body of section 6.2 after "G54", from F5-F9, F18 and F22 restated here.
std::vector<std::string> expected_motion(const LatheFlatParams& p, int layers, double clear_x,
                                         int decimals, double per_length_unit) {
  const double r2 = p.part_diameter_mm / 2.0;
  const double t = *p.flat_depth_mm;
  const double r = p.tool_radius_mm;
  const int n = *p.steps;
  const auto x_word = [&](double radius) {
    return fixed(2.0 * radius / per_length_unit, decimals);
  };
  std::vector<std::string> out;
  out.push_back("G0 X" + x_word(clear_x) + " Z" + fixed(p.z_mm / per_length_unit, decimals));
  for (int k = 0; k < p.flats; ++k) {
    for (int j = 1; j <= layers; ++j) {
      const double d = r2 - t * j / layers;
      const double alpha_e = std::acos(d / r2);
      const double offset = -k * 360.0 / p.flats;
      out.push_back("G0 C" + fixed(offset + alpha_e * 180.0 / std::numbers::pi, decimals));
      out.push_back("G1 X" + x_word((d + r) * r2 / d) + " F" +
                    fixed(p.feed_mm_per_min / per_length_unit, decimals));
      out.push_back("G93");
      for (int i = 1; i <= 2 * n; ++i) {
        const double from = alpha_e * (n - i + 1) / n;
        const double to = alpha_e * (n - i) / n;
        const double chord = (d + r) * std::fabs(std::tan(from) - std::tan(to));
        out.push_back("G1 X" + x_word((d + r) / std::cos(to)) + " C" +
                      fixed(offset + to * 180.0 / std::numbers::pi, decimals) + " F" +
                      fixed(p.feed_mm_per_min / chord, decimals));
      }
      out.push_back("G94");
      out.push_back("G0 X" + x_word(clear_x));
    }
  }
  out.push_back("M30");
  return out;
}

// The lines after G54 up to and including M30.
std::vector<std::string> motion_of(const std::string& program) {
  const std::vector<std::string> lines = lines_of(program);
  std::vector<std::string> out;
  bool started = false;
  for (const std::string& line : lines) {
    if (started) out.push_back(line);
    if (line == "G54") started = true;
    if (line == "M30") break;
  }
  return out;
}

TEST(FlatProgram, LinuxcncHeaderAndEndAsSection64) {
  const std::vector<std::string> lines = lines_of(program_of(paper_flat()));
  ASSERT_GE(lines.size(), 7U);
  EXPECT_EQ(lines[0], "%");
  EXPECT_EQ(lines[1], "(CUTCALC)");
  EXPECT_EQ(lines[2], "(CUTCALC LATHE FLAT)");
  EXPECT_EQ(lines[3].rfind("(C AXIS", 0), 0U) << lines[3];
  EXPECT_EQ(lines[4], "G21 G18 G90 G40 G49 G80 G94 G7");
  EXPECT_EQ(lines[5], "G54");
  EXPECT_EQ(lines[lines.size() - 2], "M30");
  EXPECT_EQ(lines.back(), "%");
  ProgramOptions inch;
  inch.units = Units::inch;
  EXPECT_EQ(lines_of(program_of(paper_flat(), inch))[4], "G20 G18 G90 G40 G49 G80 G94 G7");
}

TEST(FlatProgram, SinumerikHeaderAndEndAsSection64) {
  ProgramOptions options;
  options.dialect = Dialect::sinumerik;
  options.name = "FLAT_1";
  const auto out = written(paper_flat(), options);
  ASSERT_TRUE(out.ok());
  const std::vector<std::string> lines = lines_of(program_text(out.value()));
  ASSERT_GE(lines.size(), 6U);
  EXPECT_EQ(lines[0], "; FLAT_1");
  EXPECT_EQ(lines[1], "; CUTCALC LATHE FLAT");
  EXPECT_EQ(lines[2].rfind("; C AXIS", 0), 0U) << lines[2];
  EXPECT_EQ(lines[3], "G18 G710 G40 G90 G94 DIAMON");
  EXPECT_EQ(lines.back(), "M30");
  EXPECT_EQ(out.value().file_name, "FLAT_1.MPF");
  options.units = Units::inch;
  EXPECT_EQ(lines_of(program_of(paper_flat(), options))[3], "G18 G700 G40 G90 G94 DIAMON");
}

TEST(FlatProgram, WorkedExampleBlocksAreThoseOfSection62) {
  const LatheFlatParams p = paper_flat();
  EXPECT_EQ(motion_of(program_of(p)), expected_motion(p, 1, 17.0, 4, 1.0));
  // Printed ends of section 9: X 32.0000 .. 30.0000, C 20.3641 .. -20.3641.
  const std::string program = program_of(p);
  EXPECT_NE(program.find("\nG0 C20.3641\nG1 X32.0000 F100.0000\nG93\n"), std::string::npos);
  EXPECT_NE(program.find(" C-20.3641 F"), std::string::npos);
  EXPECT_NE(program.find("\nG1 X30.0000 C0.0000 F"), std::string::npos);
}

TEST(FlatProgram, FlatsAreOuterLayersInnerAndEveryG93BlockHasItsF) {
  // m = 3, L = 2, R = 3, N = 3, z = -7.5, Sinumerik-free LinuxCNC with 5 decimals.
  LatheFlatParams p = paper_flat();
  p.flats = 3;
  p.flat_depth_mm = 2.0;
  p.layer_depth_mm = 1.0;
  p.tool_radius_mm = 3.0;
  p.steps = 3;
  p.z_mm = -7.5;
  p.clearance_mm = 2.0;
  ProgramOptions options;
  options.decimals = 5;
  const double clear_x = (14.0 + 3.0) * 16.0 / 14.0 + 2.0;
  const std::vector<std::string> motion = motion_of(program_of(p, options));
  EXPECT_EQ(motion, expected_motion(p, 2, clear_x, 5, 1.0));
  // 2 N m L = 36 cutting blocks, each with C and F; 6 approach blocks with F.
  int g93_blocks = 0;
  for (const std::string& line : motion) {
    if (line.find(" C") != std::string::npos && line.rfind("G1 ", 0) == 0) {
      EXPECT_NE(line.find(" F"), std::string::npos) << line;
      ++g93_blocks;
    }
  }
  EXPECT_EQ(g93_blocks, 36);
}

TEST(FlatProgram, InchConvertsXAndTheApproachFeedButNotCOrTheInverseTimeFeed) {
  LatheFlatParams p = paper_flat();
  p.steps = 4;
  p.flats = 2;
  p.tool_radius_mm = 2.0;
  p.z_mm = 12.7;
  ProgramOptions inch;
  inch.units = Units::inch;
  inch.decimals = 6;
  const double clear_x = 17.0 * 16.0 / 15.0 + 1.0;
  EXPECT_EQ(motion_of(program_of(p, inch)), expected_motion(p, 1, clear_x, 6, 25.4));
  // The same C and G93 F words as the mm program with the same decimals.
  ProgramOptions mm;
  mm.decimals = 6;
  const std::vector<std::string> in_mm = motion_of(program_of(p, mm));
  const std::vector<std::string> in_inch = motion_of(program_of(p, inch));
  ASSERT_EQ(in_mm.size(), in_inch.size());
  for (std::size_t i = 0; i < in_mm.size(); ++i) {
    const std::size_t c_mm = in_mm[i].find(" C");
    if (c_mm == std::string::npos) continue;
    EXPECT_EQ(in_mm[i].substr(c_mm), in_inch[i].substr(in_inch[i].find(" C"))) << i;
  }
}

TEST(FlatProgram, WarningsAreUpperCaseCommentLines) {
  LatheFlatParams p = paper_flat();
  p.feed_mm_per_min = 20000.0;  // over 16 000.7
  p.flatness_tolerance_mm = 0.002;
  const std::vector<std::string> lines = lines_of(program_of(p));
  ASSERT_GE(lines.size(), 6U);
  EXPECT_EQ(lines[4], "(WARNING FEED_EXCEEDS_BLOCK_RATE)");
  EXPECT_EQ(lines[5], "(WARNING FLATNESS_OVER_TOLERANCE)");
  EXPECT_EQ(lines[6], "G21 G18 G90 G40 G49 G80 G94 G7");
  ProgramOptions sinumerik;
  sinumerik.dialect = Dialect::sinumerik;
  const std::vector<std::string> s = lines_of(program_of(p, sinumerik));
  ASSERT_GE(s.size(), 5U);
  EXPECT_EQ(s[3], "; WARNING FEED_EXCEEDS_BLOCK_RATE");
  EXPECT_EQ(s[4], "; WARNING FLATNESS_OVER_TOLERANCE");
}

TEST(FlatProgram, AnInverseTimeFeedThatPrintsAsZeroIsRefused) {
  // D1000, t = 400, N = 1: chords of 490 mm at 0.001 mm/min give F = 2e-6 per minute.
  LatheFlatParams p = paper_flat();
  p.part_diameter_mm = 1000.0;
  p.flat_depth_mm = 400.0;
  p.steps = 1;
  p.feed_mm_per_min = 0.001;
  const auto out = written(p, {});
  ASSERT_FALSE(out.ok());
  EXPECT_EQ(out.error().code, ErrorCode::word_prints_as_zero);
  // The worked example at the same feed prints F0.0019 and F0.0010: fine.
  LatheFlatParams slow = paper_flat();
  slow.feed_mm_per_min = 0.001;
  EXPECT_TRUE(written(slow, {}).ok());
}

}  // namespace
}  // namespace cutcalc::domain::lathe_flat
