// The checker must be able to fail: hand-built programs that rs274 accepts but that are 1 mm off
// the exact centre path, kinked by about 1 degree, open, or too shallow are rejected, and a
// hand-built good program (the round path of the 12-gon, within 0.1 um of the exact one) passes.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "gcode/canon_parser.h"
#include "gcode/exact_path.h"
#include "gcode/path_checker.h"
#include "gcode/rs274_runner.h"

namespace {

using cutcalc::test::gcode::check_program;
using cutcalc::test::gcode::ExactCentrePath;
using cutcalc::test::gcode::FeedCheck;
using cutcalc::test::gcode::norm;
using cutcalc::test::gcode::parse_canon;
using cutcalc::test::gcode::PathCheckReport;
using cutcalc::test::gcode::ProgramLayout;
using cutcalc::test::gcode::Rs274Run;
using cutcalc::test::gcode::run_rs274;
using cutcalc::test::gcode::Vec2;

std::string fmt4(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.4f", value);
  std::string text = buffer;
  return text == "-0.0000" ? "0.0000" : text;
}

double round4(double value) { return std::stod(fmt4(value)); }

struct HandArc {
  Vec2 end;     // 4-decimal values
  Vec2 centre;  // 4-decimal values
};

// A ramp loop from Z0 to -depth (Z linear in arc length) and one flat loop at -depth, both made of
// `loop` (G3 arcs, the last one ending at `start`); options.flat_loop replaces the flat loop.
// With c_step_deg, every arc of loop k (k = 0, 1; meant for one-block loops) carries
// C = (k + 1) c_step_deg.
struct HandOptions {
  const std::vector<HandArc>* flat_loop = nullptr;
  double feed = 100.0;  // G94 F
  std::optional<double> c_step_deg;
};

HandOptions with_flat_loop(const std::vector<HandArc>& flat_loop) {
  HandOptions options;
  options.flat_loop = &flat_loop;
  return options;
}

HandOptions with_c(double feed, double c_step_deg) {
  HandOptions options;
  options.feed = feed;
  options.c_step_deg = c_step_deg;
  return options;
}

std::string hand_program(Vec2 start, const std::vector<HandArc>& loop, double depth,
                         const HandOptions& options = {}) {
  std::vector<double> lengths;
  double total = 0.0;
  Vec2 from = start;
  for (const auto& arc : loop) {
    const double r0 = norm(from - arc.centre);
    const double r1 = norm(arc.end - arc.centre);
    double sweep = std::atan2((arc.end - arc.centre).y, (arc.end - arc.centre).x) -
                   std::atan2((from - arc.centre).y, (from - arc.centre).x);
    while (sweep <= 0.0) sweep += 2.0 * std::numbers::pi;
    lengths.push_back(sweep * (r0 + r1) / 2.0);
    total += lengths.back();
    from = arc.end;
  }
  std::string text = "%\n(HAND-BUILT CHECKER PROBE)\nG21 G17 G90 G40 G80 G94\nG0 Z5.0000\n";
  text += "G0 X" + fmt4(start.x) + " Y" + fmt4(start.y) + (options.c_step_deg ? " C0.0000" : "") +
          "\nG94 F" + fmt4(options.feed) + "\nG1 Z0.0000\n";
  const auto c_word = [&](int loop_index) {
    return options.c_step_deg ? " C" + fmt4((loop_index + 1) * *options.c_step_deg) : std::string();
  };
  from = start;
  double s = 0.0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    s += lengths[i];
    const HandArc& arc = loop[i];
    text += "G3 X" + fmt4(arc.end.x) + " Y" + fmt4(arc.end.y) + " Z" + fmt4(-depth * s / total) +
            " I" + fmt4(arc.centre.x - from.x) + " J" + fmt4(arc.centre.y - from.y) + c_word(0) +
            "\n";
    from = arc.end;
  }
  for (const auto& arc : options.flat_loop != nullptr ? *options.flat_loop : loop) {
    text += "G3 X" + fmt4(arc.end.x) + " Y" + fmt4(arc.end.y) + " I" + fmt4(arc.centre.x - from.x) +
            " J" + fmt4(arc.centre.y - from.y) + c_word(1) + "\n";
    from = arc.end;
  }
  text += "G0 Z5.0000\nM30\n%\n";
  return text;
}

ProgramLayout hand_layout(int blocks_per_loop, double tolerance_mm, double depth_mm = 0.2) {
  ProgramLayout layout;
  layout.blocks_per_loop = blocks_per_loop;
  layout.layers = 1;
  layout.loops_per_layer = 1;  // one ramp loop + one flat loop
  layout.depth_mm = depth_mm;
  layout.tolerance_mm = tolerance_mm;
  return layout;
}

// rs274 must accept the probe (the defect is one only the checker sees); then the checker runs.
PathCheckReport accepted_then_checked(const std::string& program, const ExactCentrePath& path,
                                      const ProgramLayout& layout) {
  const Rs274Run run = run_rs274(program);
  EXPECT_TRUE(run.started) << run.spawn_error;
  EXPECT_EQ(run.exit_code, 0) << run.errors << "\n" << program;
  return check_program(parse_canon(run.output), path, layout);
}

bool mentions(const PathCheckReport& report, const std::string& word) {
  return std::any_of(report.violations.begin(), report.violations.end(),
                     [&](const std::string& v) { return v.find(word) != std::string::npos; });
}

std::string listed(const PathCheckReport& report) {
  std::string text;
  for (const auto& v : report.violations) text += "  " + v + "\n";
  return text;
}

// The 12-gon's path is within 0.05 um of the circle of radius e: one full circle per loop.
TEST(GcodeCheckerSelfTest, AcceptsAHandBuiltCircleOnTheTwelveGonPath) {
  const ExactCentrePath path(12, 20.0);
  const double e = round4(path.e());
  const std::vector<HandArc> circle = {{{0.0, e}, {0.0, 0.0}}};
  const auto report =
      accepted_then_checked(hand_program({0.0, e}, circle, 0.2), path, hand_layout(1, 0.001));
  EXPECT_TRUE(report.violations.empty()) << listed(report);
  EXPECT_LT(report.max_deviation_mm, 1e-4);  // r_max - e = 0.05 um and e printed 0.036 um off
  EXPECT_LT(report.max_uncovered_mm, 1e-4);
  EXPECT_NEAR(report.max_kink_deg, 0.0, 1e-9);
  EXPECT_DOUBLE_EQ(report.final_z_mm, -0.2);
}

TEST(GcodeCheckerSelfTest, RejectsAProgramOneMillimetreOffThePath) {
  const ExactCentrePath path(4, 20.0);
  const double e = round4(path.e());
  // A circle through the start point (0, e) whose bottom lies 1 mm beyond the path's.
  const std::vector<HandArc> circle = {{{0.0, e}, {0.0, -0.5}}};
  const auto report =
      accepted_then_checked(hand_program({0.0, e}, circle, 0.2), path, hand_layout(1, 0.005));
  EXPECT_NEAR(report.max_deviation_mm, 1.0, 0.01);
  EXPECT_TRUE(mentions(report, "deviation")) << listed(report);
  EXPECT_TRUE(mentions(report, "exact path")) << listed(report);
  EXPECT_NEAR(report.max_kink_deg, 0.0, 1e-9);  // the only defect is the distance
}

// Two half circles about (+-h, 0) on the octagon's path: 2 um from it (inside 5 um), but their
// tangents meet at 2 atan(h / e) = 0.99 deg at both joins.
TEST(GcodeCheckerSelfTest, RejectsAOneDegreeTangentKink) {
  const ExactCentrePath path(8, 20.0);
  const double e = round4(path.e());
  const double h = 0.0019;
  const std::vector<HandArc> halves = {{{0.0, -e}, {h, 0.0}}, {{0.0, e}, {-h, 0.0}}};
  const auto report =
      accepted_then_checked(hand_program({0.0, e}, halves, 0.2), path, hand_layout(2, 0.005));
  EXPECT_NEAR(report.max_kink_deg, 2.0 * std::atan(h / e) * 180.0 / std::numbers::pi, 1e-9);
  EXPECT_GT(report.max_kink_deg, 0.95);
  ASSERT_EQ(report.violations.size(), 1u) << listed(report);  // the kink and nothing else
  EXPECT_TRUE(mentions(report, "kink")) << listed(report);
  EXPECT_LT(report.max_deviation_mm, 0.005);
}

TEST(GcodeCheckerSelfTest, RejectsALoopThatDoesNotClose) {
  const ExactCentrePath path(12, 20.0);
  const double e = round4(path.e());
  const std::vector<HandArc> circle = {{{0.0, e}, {0.0, 0.0}}};
  const std::vector<HandArc> quarter = {{{-e, 0.0}, {0.0, 0.0}}};
  const auto report = accepted_then_checked(
      hand_program({0.0, e}, circle, 0.2, with_flat_loop(quarter)), path, hand_layout(1, 0.001));
  EXPECT_TRUE(mentions(report, "a loop ends")) << listed(report);
  EXPECT_TRUE(mentions(report, "exact path")) << listed(report);  // 3/4 of the path uncovered
}

TEST(GcodeCheckerSelfTest, RejectsAProgramThatStopsAboveTheDepth) {
  const ExactCentrePath path(12, 20.0);
  const double e = round4(path.e());
  const std::vector<HandArc> circle = {{{0.0, e}, {0.0, 0.0}}};
  const auto report =
      accepted_then_checked(hand_program({0.0, e}, circle, 0.1), path, hand_layout(1, 0.001, 0.2));
  EXPECT_TRUE(mentions(report, "not at -depth")) << listed(report);
  EXPECT_TRUE(mentions(report, "layer levels")) << listed(report);
}

// c_axis: C = -(180/pi) t at every block end (t = rotor rotation, 360/(N-1) deg per loop) and
// G94 F = rpm (N-1) L_p. On the 12-gon circle C steps -32.7273 deg per loop; 0.2 deg off (what a
// midpoint junction rule would do, spec P21) is rejected.
TEST(GcodeCheckerSelfTest, ChecksCWordsAgainstTheRotorPhase) {
  const ExactCentrePath path(12, 20.0);
  const double e = round4(path.e());
  const std::vector<HandArc> circle = {{{0.0, e}, {0.0, 0.0}}};
  const double rpm = 40.0;
  const double feed = rpm * 11.0 * 2.0 * std::numbers::pi * e;  // L_p of a full circle of radius e
  ProgramLayout layout = hand_layout(1, 0.001);
  layout.feed_check = FeedCheck::c_axis;
  layout.spindle_speed_rpm = rpm;

  const auto good = accepted_then_checked(
      hand_program({0.0, e}, circle, 0.2, with_c(feed, -360.0 / 11.0)), path, layout);
  EXPECT_TRUE(good.violations.empty()) << listed(good);
  EXPECT_LT(good.max_c_error_deg, 1e-4);

  const auto shifted = accepted_then_checked(
      hand_program({0.0, e}, circle, 0.2, with_c(feed, -360.0 / 11.0 - 0.1)), path, layout);
  EXPECT_NEAR(shifted.max_c_error_deg, 0.2, 1e-4);  // 0.1 deg per loop, two loops
  EXPECT_TRUE(mentions(shifted, "C off the rotor phase")) << listed(shifted);

  const auto slow = accepted_then_checked(
      hand_program({0.0, e}, circle, 0.2, with_c(feed * 0.999, -360.0 / 11.0)), path, layout);
  EXPECT_TRUE(mentions(slow, "F off")) << listed(slow);
}

// The gate itself: rs274 at CENTER_ARC_RADIUS_TOLERANCE_MM = 0.001 rejects an IJ arc whose end
// radius is 2 um off, and says so.
TEST(GcodeCheckerSelfTest, Rs274RejectsARadiusMismatchAtTheStrictTolerance) {
  const Rs274Run run = run_rs274(
      "%\nG21 G17 G90\nG0 X0.0000 Y1.0000\nG1 F100.0000 Z0.0000\n"
      "G3 X-1.0020 Y0.0000 I0.0000 J-1.0000\nM30\n%\n");
  ASSERT_TRUE(run.started) << run.spawn_error;
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.errors.find("Radius to end of arc differs"), std::string::npos) << run.errors;
  // 1.5 um: over both 0.001 mm and 0.1 % of r = 1 mm, refused; 0.9 um passes.
  const Rs274Run slight = run_rs274(
      "%\nG21 G17 G90\nG0 X0.0000 Y1.0000\nG1 F100.0000 Z0.0000\n"
      "G3 X-1.0015 Y0.0000 I0.0000 J-1.0000\nM30\n%\n");
  EXPECT_EQ(slight.exit_code, 1) << slight.errors;
  const Rs274Run within = run_rs274(
      "%\nG21 G17 G90\nG0 X0.0000 Y1.0000\nG1 F100.0000 Z0.0000\n"
      "G3 X-1.0009 Y0.0000 I0.0000 J-1.0000\nM30\n%\n");
  EXPECT_EQ(within.exit_code, 0) << within.errors;
}

TEST(GcodeCheckerSelfTest, MissingRs274IsAFailureNotASkip) {
  const Rs274Run run = run_rs274("%\nM30\n%\n", "/nonexistent/rs274");
  EXPECT_FALSE(run.started);
  EXPECT_NE(run.spawn_error.find("linuxcnc-uspace"), std::string::npos) << run.spawn_error;
}

}  // namespace
