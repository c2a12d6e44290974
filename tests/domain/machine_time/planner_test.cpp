// The planner against closed forms (spec machine-time.md M3-M8): each test's figure is worked out
// by hand from LinuxCNC 2.9's rules, independently of the code.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "domain/machine_time/trapezoid.h"
#include "machine_time_test_support.h"

namespace cutcalc::domain::machine_time {
namespace {

using test::router;
using test::time_of;

constexpr double kPeriod = 0.001;

TEST(Trapezoid, ReachesItsVelocityAndCruises) {
  // 80 mm at 200 mm/s, 1000 mm/s^2: 0.2 s up, 0.2 s down, 60 mm at 200 mm/s.
  const Trapezoid t = plan_trapezoid(80.0, 0.0, 0.0, 200.0, 1000.0);
  EXPECT_NEAR(t.duration_s, 0.6, 1e-12);
  EXPECT_NEAR(t.accel_s, 0.2, 1e-12);
  EXPECT_NEAR(t.cruise_s, 0.2, 1e-12);
}

TEST(Trapezoid, ShortMoveIsATriangle) {
  // 4 mm at 1000 mm/s^2: 2 sqrt(L/a) = 0.1265 s, peak sqrt(a L) = 63.2 mm/s.
  const Trapezoid t = plan_trapezoid(4.0, 0.0, 0.0, 200.0, 1000.0);
  EXPECT_NEAR(t.duration_s, 2.0 * std::sqrt(4.0 / 1000.0), 1e-12);
  EXPECT_NEAR(t.v_peak, std::sqrt(4000.0), 1e-9);
}

TEST(Trapezoid, EndVelocityTheLengthCannotReachIsLowered) {
  const Trapezoid t = plan_trapezoid(1.0, 0.0, 100.0, 200.0, 1000.0);
  EXPECT_NEAR(t.v_end, std::sqrt(2000.0), 1e-9);
}

TEST(Planner, ExactStopRapidIsATrapezoidPlusHalfAPeriod) {
  const ProgramTime time = time_of("G21 G90 G17 G61.1\nG0 X80\nM2\n");
  EXPECT_NEAR(time.estimated_s, 0.6 + 0.5 * kPeriod, 1e-9);
  EXPECT_NEAR(time.nominal_s, 80.0 / 200.0, 1e-12);
  EXPECT_NEAR(time.rapid_s, time.estimated_s, 1e-12);
  EXPECT_NEAR(time.rapid_length_mm, 80.0, 1e-12);
}

TEST(Planner, AccelerationAlongAMoveIsTheSlowestAxisShare) {
  // u = (0.8, 0.6): a = min(1000/0.8, 1000/0.6) = 1250; F3000 = 50 mm/s over 50 mm.
  const ProgramTime time = time_of("G21 G90 G61.1\nF3000\nG1 X40 Y30\nM2\n");
  EXPECT_NEAR(time.estimated_s, 50.0 / 1250.0 + 1.0 + 0.5 * kPeriod, 1e-9);
}

TEST(Planner, BlendModeHalvesTheAccelerationOfALoneMove) {
  // G64: the last segment keeps its parabolic termination, so a = 500 (tcGetOverallMaxAccel).
  const ProgramTime time = time_of("G21 G90 G64\nG0 X80\nM2\n");
  EXPECT_NEAR(time.estimated_s, 200.0 / 500.0 + 80.0 / 200.0 + 0.5 * kPeriod, 1e-9);
}

TEST(Planner, ExactPathCornersLoseTenPercentOfTheAcceleration) {
  // G61 keeps the kink of a corner it does not blend: a = 0.9 * 1000 on both sides of it.
  const std::string square = "G21 G90 G61\nF4000\nG1 X60\nG1 Y60\nM2\n";
  const double v = 4000.0 / 60.0;
  const double one_side = v / 900.0 + 60.0 / v + 0.5 * kPeriod;
  EXPECT_NEAR(time_of(square).estimated_s, 2.0 * one_side, 1e-9);
}

TEST(Planner, RapidNeverBlendsWithAFeedMove) {
  // handleModeChange stops between them: the rapid runs at full acceleration.
  const ProgramTime time = time_of("G21 G90 G64\nG0 X4\nF600\nG1 X8\nM2\n");
  const double rapid = 2.0 * std::sqrt(4.0 / 1000.0) + 0.5 * kPeriod;
  const double feed = 10.0 / 500.0 + 4.0 / 10.0 + 0.5 * kPeriod;  // G64: a = 500, v = 10 mm/s
  EXPECT_NEAR(time.estimated_s, rapid + feed, 1e-9);
  EXPECT_NEAR(time.rapid_s, rapid, 1e-9);
}

TEST(Planner, ArcSpeedIsCappedByNormalAcceleration) {
  // A finalised arc R1 (another move follows it) in G61.1: v <= sqrt(0.866 a r) = 29.4 mm/s,
  // far below F6000, and its tangential acceleration is a / 2.
  const std::string program = "G21 G90 G61.1\nG1 X1 F6000\nG3 X1 Y0 I-1 J0\nG1 X2\nM2\n";
  const ProgramTime time = time_of(program);
  const double v_arc = std::sqrt(0.8660254037844386 * 1000.0 * 1.0);
  const double arc = v_arc / 500.0 + 2.0 * M_PI / v_arc + 0.5 * kPeriod;
  const double line = 2.0 * std::sqrt(1.0 / 1000.0) + 0.5 * kPeriod;
  EXPECT_NEAR(time.estimated_s, 2.0 * line + arc, 1e-6);
  ASSERT_FALSE(time.slowest_blocks.empty());
  EXPECT_EQ(time.slowest_blocks.front().line, 3U);
  EXPECT_EQ(time.slowest_blocks.front().limited_by, Limit::arc);
}

TEST(Planner, ShortSegmentsRunAtOneSegmentPerServoPeriod) {
  // 0.05 mm moves at F12000 (200 mm/s): at most 0.05 mm per 1 ms = 50 mm/s.
  std::string program = "G21 G90 G61.1\nF12000\n";
  for (int i = 1; i <= 4; ++i) program += "G1 X" + std::to_string(0.05 * i) + "\n";
  const ProgramTime time = time_of(program);
  bool warned = false;
  for (const auto& w : time.warnings)
    warned = warned || w.code == program::WarningCode::segment_too_short;
  EXPECT_TRUE(warned);
  EXPECT_GT(time.estimated_s, 4 * (0.05 / 50.0));
}

TEST(Planner, DwellIsTimedAndFlushesTheQueue) {
  const ProgramTime time = time_of("G21 G90 G61.1\nF2000\nG1 X20\nG4 P0.5\nG1 X40\nM2\n");
  EXPECT_NEAR(time.dwell_s, 0.5, 1e-12);
  const double v = 2000.0 / 60.0;
  const double move = v / 1000.0 + 20.0 / v + 0.5 * kPeriod;
  EXPECT_NEAR(time.estimated_s, 2.0 * move + 0.5 + 0.0035, 1e-9);
  EXPECT_NEAR(time.nominal_s, 2.0 * 20.0 / v + 0.5, 1e-9);
}

TEST(Planner, BlendWithoutToleranceShortensTheSquare) {
  // machine-time.md section 1: in G64 without P the blended path is shorter than programmed.
  const ProgramTime g64 = time_of("G21 G90 G64\nF4000\nG1 X60\nG1 Y60\nG1 X0\nG1 Y0\nM2\n");
  EXPECT_LT(g64.feed_length_mm, 240.0);
  EXPECT_LT(g64.estimated_s, g64.nominal_s);
  EXPECT_LT(g64.estimated_s - g64.nominal_s, 0.0);
}

TEST(Planner, ProfileStartsAndEndsAtRestAndPeaksAtTheFeed) {
  const ProgramTime time =
      time_of("G21 G90 G61.1\nG0 X80\nM2\n", router(), program::Dialect::linuxcnc, 101);
  ASSERT_EQ(time.profile.size(), 101U);
  EXPECT_NEAR(time.profile.front().velocity_per_s, 0.0, 1e-9);
  EXPECT_NEAR(time.profile.back().t_s, time.estimated_s, 1e-12);
  double peak = 0.0;
  for (const auto& p : time.profile) peak = std::max(peak, p.velocity_per_s);
  EXPECT_NEAR(peak, 200.0, 1e-9);
  EXPECT_NEAR(time.profile[50].velocity_per_s, 200.0, 1e-9);
}

TEST(Planner, AxisTheMachineDoesNotDescribeIsRefused) {
  Machine xz;
  xz.axes[index(Axis::x)] = AxisLimits{100.0, 1000.0};
  xz.axes[index(Axis::z)] = AxisLimits{100.0, 1000.0};
  ProgramTimeParams params;
  params.program = "G21 G90\nF1000\nG1 X10\nG1 Y5\nM2\n";
  params.machine = xz;
  const ProgramTimeOutcome outcome = time_program(params);
  const auto* missing = std::get_if<AxisNotDescribed>(&outcome);
  ASSERT_NE(missing, nullptr);
  EXPECT_EQ(missing->axis, Axis::y);
  EXPECT_EQ(missing->line, 4U);
}

TEST(Planner, UnitsNotStatedAreWarnedAbout) {
  const ProgramTime time = time_of("G90\nG0 X10\nM2\n");
  ASSERT_EQ(time.warnings.size(), 1U);
  EXPECT_EQ(time.warnings[0].code, program::WarningCode::units_assumed);
}

TEST(Planner, LookAheadHoldsAQueueNotTheProgram) {
  // 20 000 collinear 0.5 mm moves in G64 run through at the feed: the first and last ramps only.
  std::string program = "G21 G90 G64\nF6000\n";
  for (int i = 1; i <= 20000; ++i) program += "G1 X" + std::to_string(0.5 * i) + "\n";
  const ProgramTime time = time_of(program);
  const double nominal = 10000.0 / 100.0;
  EXPECT_NEAR(time.nominal_s, nominal, 1e-6);
  EXPECT_NEAR(time.estimated_s, nominal, 0.25);
  EXPECT_GT(time.estimated_s, nominal);
}

}  // namespace
}  // namespace cutcalc::domain::machine_time
