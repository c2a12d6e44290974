// The cycle's lathe program (grooving-cycle.md section 5): the block order of 5.1, the headers of
// 5.2, the comment lines, the Fanuc rounding warning and the words that would print as zero.

#include "domain/grooving/grooving_program.h"
#include "domain/grooving/grooving_settings.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace cutcalc::domain::grooving {
namespace {

using settings::small_groove;

using program::Coolant;
using program::Dialect;
using program::ProgramOptions;
using program::Units;
using program::WarningCode;

GroovingCycleParams with_css(GroovingCycleParams p, double v, double n_max) {
  p.spindle = {std::nullopt, v, n_max};
  return p;
}

Result<GroovingProgram> written(const GroovingCycleParams& p, const ProgramOptions& options) {
  const auto cycle = compute_grooving_cycle(p);
  if (!cycle.ok()) return cycle.error();
  return write_grooving_program(p, cycle.value(), options);
}

GroovingProgram program_of(const GroovingCycleParams& p, const ProgramOptions& options) {
  const auto out = written(p, options);
  EXPECT_TRUE(out.ok()) << (out.ok() ? "" : error_code_name(out.error().code));
  return out.ok() ? out.value() : GroovingProgram{};
}

// The whole text of a program (none when it was refused).
std::string text_of(const GroovingProgram& program) {
  return program.program ? program_text(program) : std::string{};
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> first_lines(const std::string& text, std::size_t count) {
  std::vector<std::string> lines = lines_of(text);
  lines.resize(std::min(count, lines.size()));
  return lines;
}

std::vector<WarningCode> codes(const GroovingProgram& program) {
  std::vector<WarningCode> out;
  for (const auto& warning : program.warnings) out.push_back(warning.code);
  return out;
}

ErrorCode refusal(const GroovingCycleParams& p, const ProgramOptions& options) {
  const auto out = written(p, options);
  EXPECT_FALSE(out.ok());
  return out.ok() ? ErrorCode::not_converged : out.error().code;
}

TEST(GroovingProgram, BlocksFollowSection51AndFeedsPrintOnlyOnChange) {
  // N = 5 (ends left, the final shift goes right), coolant on, linuxcnc mm, 4 decimals: approach,
  // spindle, coolant, air cut, 5 pattern blocks, dwell 60/500 s, final shift, retract, M5, M9.
  ProgramOptions options;
  options.coolant = Coolant::flood;
  const GroovingProgram out = program_of(small_groove(5), options);
  EXPECT_EQ(text_of(out),
            "%\n"
            "(CUTCALC)\n"
            "(CUTCALC GROOVING CYCLE V RAZVOD)\n"
            "G21 G18 G7 G90 G40 G49 G80 G95\n"
            "G54\n"
            "G0 X52.0000 Z-10.0000\n"
            "G97 S500.0000 M3\n"
            "M8\n"
            "G1 X50.0000 F0.1000\n"
            "G1 X49.8000\n"
            "G1 X49.6000 Z-9.6000 F0.4123\n"
            "G1 X49.4000 F0.1000\n"
            "G1 X49.2000 Z-10.0000 F0.4123\n"
            "G1 X49.0000 F0.1000\n"
            "G4 P0.120\n"
            "G1 Z-9.6000\n"
            "G0 X52.0000\n"
            "M5\n"
            "M9\n"
            "M30\n"
            "%\n");
  EXPECT_EQ(out.file_name, "CUTCALC.ngc");
  EXPECT_TRUE(out.warnings.empty());
}

TEST(GroovingProgram, FinalShiftPrintsItsFeedAfterAShiftBlockAndGoesToTheOtherSide) {
  // N = 4: the last pattern block is a shift back to z_L at f_sh; the final shift goes to z_R at s.
  const std::vector<std::string> lines = lines_of(text_of(program_of(small_groove(4), {})));
  ASSERT_GE(lines.size(), 7U);
  const std::size_t end = lines.size();
  EXPECT_EQ(lines[end - 7], "G1 X49.2000 Z-10.0000 F0.4123");
  EXPECT_EQ(lines[end - 6], "G4 P0.120");
  EXPECT_EQ(lines[end - 5], "G1 Z-9.6000 F0.1000");
  EXPECT_EQ(lines[end - 4], "G0 X52.0000");
  // N = 6 ends right: the final shift goes back to z_L.
  const std::vector<std::string> six = lines_of(text_of(program_of(small_groove(6), {})));
  ASSERT_GE(six.size(), 5U);
  EXPECT_EQ(six[six.size() - 5], "G1 Z-10.0000 F0.1000");
}

TEST(GroovingProgram, NoDwellBlockWithoutDwellRevolutions) {
  GroovingCycleParams p = small_groove(5);
  p.dwell_revolutions = 0.0;
  const std::string text = text_of(program_of(p, {}));
  EXPECT_EQ(text.find("\nG4 "), std::string::npos) << text;
  EXPECT_NE(text.find("G1 X49.0000 F0.1000\nG1 Z-9.6000\n"), std::string::npos) << text;
}

TEST(GroovingProgram, FanucHeaderSpindleClampAndDwellAsSection52) {
  ProgramOptions options;
  options.dialect = Dialect::fanuc;
  options.program_number = 12;
  options.name = "GROOVE";
  options.tool_number = 7;
  options.coolant = Coolant::mist;
  const GroovingProgram out = program_of(with_css(small_groove(5), 86.0, 1000.0), options);
  EXPECT_EQ(first_lines(text_of(out), 12),
            (std::vector<std::string>{"%", "O0012 (GROOVE)", "(CUTCALC GROOVING CYCLE V RAZVOD)",
                                      "G21", "G18 G40 G99", "G54", "T0707", "G00 X52.000 Z-10.000",
                                      "G50 S1000", "G96 S86 M03", "M07", "G01 X50.000 F0.100"}));
  // Dwell at Db 49: n = 86000/(pi 49) = 558.66 rpm, 1 rev = 0.107 s.
  EXPECT_NE(text_of(out).find("\nG04 X0.107\n"), std::string::npos) << text_of(out);
  EXPECT_NE(text_of(out).find("\nM05\nM09\nM30\n%\n"), std::string::npos) << text_of(out);
  EXPECT_EQ(out.file_name, "O0012.nc");
  EXPECT_TRUE(out.warnings.empty());
}

TEST(GroovingProgram, SinumerikInchHeaderAndSurfaceSpeedInFeetPerMinute) {
  ProgramOptions options;
  options.dialect = Dialect::sinumerik;
  options.units = Units::inch;
  options.name = "GROOVE_1";
  options.tool_number = 3;
  options.work_offset = 55;
  const GroovingProgram out = program_of(with_css(small_groove(5), 86.0, 1000.0), options);
  // 52/25.4 = 2.04724, -10/25.4 = -0.39370, 86/0.3048 = 282.15223 ft/min; 0.1/25.4 = 0.003937.
  EXPECT_EQ(first_lines(text_of(out), 9),
            (std::vector<std::string>{"; GROOVE_1", "; CUTCALC GROOVING CYCLE V RAZVOD",
                                      "G18 G700 G40 G90 G95 DIAMON", "G55", "T3 D1",
                                      "G0 X2.0472 Z-0.3937", "G96 S282.1522 LIMS=1000.0000 M3",
                                      "G1 X1.9685 F0.0039", "G1 X1.9606"}));
  EXPECT_NE(text_of(out).find("\nG4 F0.107\n"), std::string::npos) << text_of(out);
  EXPECT_NE(text_of(out).find("\nG0 X2.0472\nM5\nM30\n"), std::string::npos) << text_of(out);
  EXPECT_EQ(out.file_name, "GROOVE_1.MPF");
}

TEST(GroovingProgram, LinuxcncInchHeaderAndConstantSpeedLine) {
  ProgramOptions options;
  options.units = Units::inch;
  options.tool_number = 12;
  const GroovingProgram out = program_of(small_groove(5), options);
  EXPECT_EQ(first_lines(text_of(out), 8),
            (std::vector<std::string>{"%", "(CUTCALC)", "(CUTCALC GROOVING CYCLE V RAZVOD)",
                                      "G20 G18 G7 G90 G40 G49 G80 G95", "G54", "T12 M6 G43",
                                      "G0 X2.04724 Z-0.39370", "G97 S500.00000 M3"}));
}

TEST(GroovingProgram, WarningsBecomeCommentLinesUpperCaseOnFanuc) {
  // X2 0.6 (outside 0.3-0.5) and N = 2 (< 5): two warnings, one comment line each, after the title.
  GroovingCycleParams p = small_groove(2);
  p.shift_mm = 0.6;
  const GroovingProgram linuxcnc = program_of(p, {});
  EXPECT_EQ(codes(linuxcnc), (std::vector{WarningCode::shift_outside_paper_range,
                                          WarningCode::pattern_not_repeated}));
  EXPECT_EQ(first_lines(text_of(linuxcnc), 5),
            (std::vector<std::string>{"%", "(CUTCALC)", "(CUTCALC GROOVING CYCLE V RAZVOD)",
                                      "(shift_outside_paper_range)", "(pattern_not_repeated)"}));
  ProgramOptions fanuc;
  fanuc.dialect = Dialect::fanuc;
  EXPECT_EQ(first_lines(text_of(program_of(p, fanuc)), 5),
            (std::vector<std::string>{"%", "O0001 (CUTCALC)", "(CUTCALC GROOVING CYCLE V RAZVOD)",
                                      "(SHIFT_OUTSIDE_PAPER_RANGE)", "(PATTERN_NOT_REPEATED)"}));
  ProgramOptions sinumerik;
  sinumerik.dialect = Dialect::sinumerik;
  EXPECT_EQ(first_lines(text_of(program_of(p, sinumerik)), 4),
            (std::vector<std::string>{"; CUTCALC", "; CUTCALC GROOVING CYCLE V RAZVOD",
                                      "; shift_outside_paper_range", "; pattern_not_repeated"}));
}

TEST(GroovingProgram, FanucAloneWarnsThatItsSpindleWordsWereRounded) {
  ProgramOptions fanuc;
  fanuc.dialect = Dialect::fanuc;
  // Integral v, n_max and n: no warning.
  EXPECT_TRUE(program_of(with_css(small_groove(5), 86.0, 1000.0), fanuc).warnings.empty());
  EXPECT_TRUE(program_of(small_groove(5), fanuc).warnings.empty());
  // v 86.4 -> S86; n_max 1000.5 -> G50 S1000; n 500.5 -> S501 (half up).
  for (const GroovingCycleParams& p :
       {with_css(small_groove(5), 86.4, 1000.0), with_css(small_groove(5), 86.0, 1000.5)}) {
    const GroovingProgram out = program_of(p, fanuc);
    EXPECT_EQ(codes(out), std::vector{WarningCode::spindle_speed_rounded});
    EXPECT_NE(text_of(out).find("(SPINDLE_SPEED_ROUNDED)\n"), std::string::npos);
    EXPECT_NE(text_of(out).find("\nG50 S1000\nG96 S86 M03\n"), std::string::npos) << text_of(out);
    EXPECT_TRUE(program_of(p, {}).warnings.empty());  // linuxcnc prints the decimals
  }
  GroovingCycleParams g97 = small_groove(5);
  g97.spindle.spindle_speed_rpm = 500.5;
  const GroovingProgram rounded = program_of(g97, fanuc);
  EXPECT_EQ(codes(rounded), std::vector{WarningCode::spindle_speed_rounded});
  EXPECT_NE(text_of(rounded).find("\nG97 S501 M03\n"), std::string::npos) << text_of(rounded);
  // Last, after the cycle's own warnings.
  g97.shift_mm = 0.6;
  EXPECT_EQ(codes(program_of(g97, fanuc)), (std::vector{WarningCode::shift_outside_paper_range,
                                                        WarningCode::spindle_speed_rounded}));
}

TEST(GroovingProgram, WordsThatWouldPrintAsZeroAreRefused) {
  // F: s = 0.00004 mm/rev prints 0.0000 at 4 decimals, but not at 6.
  GroovingCycleParams tiny_feed = small_groove(5);
  tiny_feed.feed_per_rev_mm = 0.00004;
  tiny_feed.groove_depth_mm = 0.4;
  EXPECT_EQ(refusal(tiny_feed, {}), ErrorCode::word_prints_as_zero);
  ProgramOptions six;
  six.decimals = 6;
  EXPECT_TRUE(written(tiny_feed, six).ok());
  // Fanuc G50 S: n_max 0.9 floors to 0; Fanuc G97 S: 0.4 rounds to 0.
  ProgramOptions fanuc;
  fanuc.dialect = Dialect::fanuc;
  EXPECT_EQ(refusal(with_css(small_groove(5), 86.0, 0.9), fanuc), ErrorCode::word_prints_as_zero);
  GroovingCycleParams slow = small_groove(5);
  slow.spindle.spindle_speed_rpm = 0.4;
  EXPECT_EQ(refusal(slow, fanuc), ErrorCode::word_prints_as_zero);
  EXPECT_TRUE(written(slow, {}).ok());  // "G97 S0.4000"
  // LinuxCNC G96 D and S, Sinumerik LIMS.
  EXPECT_EQ(refusal(with_css(small_groove(5), 86.0, 0.00001), {}), ErrorCode::word_prints_as_zero);
  EXPECT_EQ(refusal(with_css(small_groove(5), 0.00001, 1000.0), {}),
            ErrorCode::word_prints_as_zero);
  ProgramOptions sinumerik;
  sinumerik.dialect = Dialect::sinumerik;
  EXPECT_EQ(refusal(with_css(small_groove(5), 86.0, 0.0001), sinumerik),
            ErrorCode::word_prints_as_zero);
  // A dwell of 1e-6 revolutions prints G4 P0.000; no dwell (n_d = 0) is no error.
  GroovingCycleParams blink = small_groove(5);
  blink.dwell_revolutions = 1e-6;
  EXPECT_EQ(refusal(blink, {}), ErrorCode::word_prints_as_zero);
  blink.dwell_revolutions = 0.0;
  EXPECT_TRUE(written(blink, {}).ok());
}

}  // namespace
}  // namespace cutcalc::domain::grooving
