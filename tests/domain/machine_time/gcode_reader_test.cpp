// The G-code reader (spec machine-time.md section 4): start state, units, distance modes, arcs in
// the three planes, lathe diameter modes, feed and spindle state, path control per dialect (and
// section 7), comments of each dialect, every refusal with its line, column and word, the summary
// (blocks, stated units, first line moving each axis) and the end of the program.

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "domain/machine_time/gcode_reader.h"

namespace cutcalc::domain::machine_time {
namespace {

using program::Dialect;

constexpr double kTol = 1e-9;

struct Read {
  std::vector<Move> moves;         // every move but the queue flushes (kept apart below)
  std::vector<std::size_t> syncs;  // the lines of the flushes (MoveKind::sync)
  ReadSummary summary;
  std::optional<ReadError> error;
};

Read read(std::string_view text, Dialect dialect = Dialect::linuxcnc,
          MachineKind kind = MachineKind::mill, double max_spindle_rpm = 0.0) {
  Read out;
  ReadOptions options;
  options.dialect = dialect;
  options.kind = kind;
  options.max_spindle_rpm = max_spindle_rpm;
  const auto result = read_program(text, options, [&out](const Move& move) {
    if (move.kind == MoveKind::sync) {
      out.syncs.push_back(move.line);
    } else {
      out.moves.push_back(move);
    }
  });
  if (const auto* error = std::get_if<ReadError>(&result)) {
    out.error = *error;
  } else {
    out.summary = std::get<ReadSummary>(result);
  }
  return out;
}

// The program reads without a refusal.
Read ok(std::string_view text, Dialect dialect = Dialect::linuxcnc,
        MachineKind kind = MachineKind::mill, double max_spindle_rpm = 0.0) {
  Read out = read(text, dialect, kind, max_spindle_rpm);
  EXPECT_FALSE(out.error.has_value()) << "refused at line " << out.error->line << " column "
                                      << out.error->column << " word '" << out.error->word << "'\n"
                                      << text;
  // A refused program has failed its test already; default moves let the test go on to report
  // its other expectations instead of reading past the end.
  if (out.error) out.moves.resize(out.moves.size() + 16);
  return out;
}

double at(const AxisVector& v, Axis axis) { return v[index(axis)]; }

void expect_refusal(std::string_view text, Refusal refusal, std::size_t line, std::size_t column,
                    std::string_view word, Dialect dialect = Dialect::linuxcnc,
                    MachineKind kind = MachineKind::mill) {
  const Read out = read(text, dialect, kind);
  ASSERT_TRUE(out.error.has_value()) << text;
  EXPECT_EQ(out.error->refusal, refusal) << text;
  EXPECT_EQ(out.error->line, line) << text;
  EXPECT_EQ(out.error->column, column) << text;
  EXPECT_EQ(out.error->word, word) << text;
}

// ---- start state, units, distance modes

TEST(GcodeReader, StartsAtTheOriginInMillimetresAbsolute) {
  const Read out = ok("G0 X10 Y20 Z-5\nG0 X15\n");
  ASSERT_EQ(out.moves.size(), 2U);
  const Move& first = out.moves[0];
  EXPECT_EQ(first.kind, MoveKind::rapid);
  EXPECT_EQ(first.line, 1U);
  for (const double v : first.start) EXPECT_EQ(v, 0.0);
  EXPECT_NEAR(at(first.end, Axis::x), 10.0, kTol);
  EXPECT_NEAR(at(first.end, Axis::y), 20.0, kTol);
  EXPECT_NEAR(at(first.end, Axis::z), -5.0, kTol);
  // Absolute: X15 is a position, the other axes stay.
  EXPECT_NEAR(at(out.moves[1].end, Axis::x), 15.0, kTol);
  EXPECT_NEAR(at(out.moves[1].end, Axis::y), 20.0, kTol);
  EXPECT_EQ(out.moves[1].start, first.end);
  EXPECT_FALSE(out.summary.units_stated);
}

TEST(GcodeReader, InchProgramIsReadInMillimetresAndMillimetresPerMinute) {
  const Read out = ok("G20 G90\nG1 X1 Y-2.5 F10\n");
  ASSERT_EQ(out.moves.size(), 1U);
  EXPECT_NEAR(at(out.moves[0].end, Axis::x), 25.4, kTol);
  EXPECT_NEAR(at(out.moves[0].end, Axis::y), -63.5, kTol);
  EXPECT_EQ(out.moves[0].feed.mode, FeedMode::units_per_min);
  EXPECT_NEAR(out.moves[0].feed.value, 254.0, kTol);
  EXPECT_TRUE(out.summary.units_stated);
}

TEST(GcodeReader, MetricWordsOfEachDialectStateTheUnits) {
  EXPECT_TRUE(ok("G21\nG0 X1\n").summary.units_stated);
  EXPECT_TRUE(ok("G21\nG00 X1.\n", Dialect::fanuc).summary.units_stated);
  EXPECT_TRUE(ok("G710\nG0 X1\n", Dialect::sinumerik).summary.units_stated);
  EXPECT_TRUE(ok("G71\nG0 X1\n", Dialect::sinumerik).summary.units_stated);
  // Only before the first move.
  EXPECT_FALSE(ok("G0 X1\nG21\n").summary.units_stated);
}

TEST(GcodeReader, SinumerikInchG700ConvertsFeedsButG70OnlyLengths) {
  const Read g700 = ok("G700 G94\nG1 X1 F10\n", Dialect::sinumerik);
  EXPECT_NEAR(at(g700.moves[0].end, Axis::x), 25.4, kTol);
  EXPECT_NEAR(g700.moves[0].feed.value, 254.0, kTol);
  const Read g70 = ok("G70 G94\nG1 X1 F10\n", Dialect::sinumerik);
  EXPECT_NEAR(at(g70.moves[0].end, Axis::x), 25.4, kTol);
  EXPECT_NEAR(g70.moves[0].feed.value, 10.0, kTol);
}

TEST(GcodeReader, RotaryAxesStayInDegreesInInch) {
  const Read out = ok("G20\nG1 X1 A90 F10\nG1 C45\n");
  ASSERT_EQ(out.moves.size(), 2U);
  EXPECT_NEAR(at(out.moves[0].end, Axis::x), 25.4, kTol);
  EXPECT_NEAR(at(out.moves[0].end, Axis::a), 90.0, kTol);
  EXPECT_NEAR(out.moves[0].feed.value, 254.0, kTol);  // a linear move: in/min -> mm/min
  // A rotary-only move: F is degrees per minute, unscaled.
  EXPECT_NEAR(at(out.moves[1].end, Axis::c), 45.0, kTol);
  EXPECT_NEAR(out.moves[1].feed.value, 10.0, kTol);
}

TEST(GcodeReader, IncrementalG91AddsToThePosition) {
  const Read out = ok("G0 X10 Y10\nG91\nG0 X5 Y-2\nG0 X5\nG90\nG0 X0\n");
  ASSERT_EQ(out.moves.size(), 4U);
  EXPECT_NEAR(at(out.moves[1].end, Axis::x), 15.0, kTol);
  EXPECT_NEAR(at(out.moves[1].end, Axis::y), 8.0, kTol);
  EXPECT_NEAR(at(out.moves[2].end, Axis::x), 20.0, kTol);
  EXPECT_NEAR(at(out.moves[3].end, Axis::x), 0.0, kTol);
  EXPECT_NEAR(at(out.moves[3].end, Axis::y), 8.0, kTol);
}

TEST(GcodeReader, IncrementalInInchScalesTheIncrement) {
  const Read out = ok("G20 G91\nG0 X1\nG0 X1\n");
  EXPECT_NEAR(at(out.moves[1].end, Axis::x), 50.8, kTol);
}

TEST(GcodeReader, G92ShiftsTheProgramOriginAndG921CancelsIt) {
  const Read out = ok("G0 X10\nG92 X0\nG0 X5\nG92.1\nG0 X5\n");
  ASSERT_EQ(out.moves.size(), 3U);
  EXPECT_NEAR(at(out.moves[1].end, Axis::x), 15.0, kTol);
  EXPECT_NEAR(at(out.moves[2].end, Axis::x), 5.0, kTol);
}

TEST(GcodeReader, WorkOffsetsAndToolLengthOffsetsChangeNoPosition) {
  const Read out = ok("G54\nG0 X1\nG55\nG43 H3 Z10\nG49\nG59.1\nG0 X2\n");
  ASSERT_EQ(out.moves.size(), 3U);
  EXPECT_NEAR(at(out.moves[1].end, Axis::z), 10.0, kTol);
  EXPECT_NEAR(at(out.moves[2].end, Axis::x), 2.0, kTol);
  // Fanuc's additional offsets G54.1 P, Sinumerik's G500 and G505-G599.
  EXPECT_EQ(ok("G54.1 P7\nG00 X1.\n", Dialect::fanuc).moves.size(), 1U);
  EXPECT_EQ(ok("G500\nG505\nG0 X1\n", Dialect::sinumerik).moves.size(), 1U);
  // Sinumerik G58/G59 are programmable offsets (programs.md 2), not work offsets.
  expect_refusal("G58 X1\n", Refusal::unsupported_word, 1, 1, "G58", Dialect::sinumerik);
}

TEST(GcodeReader, ZeroLengthMoveIsStillAMove) {
  const Read out = ok("G1 X0 F100\n");
  ASSERT_EQ(out.moves.size(), 1U);
  EXPECT_EQ(out.moves[0].start, out.moves[0].end);
  EXPECT_EQ(out.summary.first_line_moving[index(Axis::x)], 0U);
}

TEST(GcodeReader, MotionIsModal) {
  const Read out = ok("G1 X1 F100\nX2\nY3\nG0 Z1\nX0\n");
  ASSERT_EQ(out.moves.size(), 5U);
  EXPECT_EQ(out.moves[1].kind, MoveKind::line);
  EXPECT_EQ(out.moves[2].kind, MoveKind::line);
  EXPECT_EQ(out.moves[4].kind, MoveKind::rapid);
}

// ---- arcs

TEST(GcodeReader, ArcInXyTakesItsCentreIncrementallyFromIJ) {
  const Read out = ok("G0 X10 Y0\nG3 X0 Y10 I-10 J0 F500\n");
  ASSERT_EQ(out.moves.size(), 2U);
  const Move& arc = out.moves[1];
  EXPECT_EQ(arc.kind, MoveKind::arc);
  EXPECT_EQ(arc.arc.plane, Plane::xy);
  EXPECT_FALSE(arc.arc.clockwise);
  EXPECT_NEAR(arc.arc.centre[0], 0.0, kTol);
  EXPECT_NEAR(arc.arc.centre[1], 0.0, kTol);
  EXPECT_EQ(arc.arc.extra_turns, 0);
  EXPECT_NEAR(arc.feed.value, 500.0, kTol);
}

TEST(GcodeReader, ArcInXzOrdersItsCentreZThenX) {
  const Read out = ok("G18\nG0 X10 Z0\nG2 X0 Z10 I-10 K0 F500\n");
  const Move& arc = out.moves.back();
  EXPECT_EQ(arc.arc.plane, Plane::xz);
  EXPECT_TRUE(arc.arc.clockwise);
  EXPECT_NEAR(arc.arc.centre[0], 0.0, kTol);  // Z
  EXPECT_NEAR(arc.arc.centre[1], 0.0, kTol);  // X
  const Read shifted = ok("G18\nG0 X10 Z5\nG2 X0 Z15 I-10 K0 F500\n");
  EXPECT_NEAR(shifted.moves.back().arc.centre[0], 5.0, kTol);
  EXPECT_NEAR(shifted.moves.back().arc.centre[1], 0.0, kTol);
}

TEST(GcodeReader, ArcInYzOrdersItsCentreYThenZ) {
  const Read out = ok("G19\nG0 Y10 Z2\nG3 Y3 Z9 J-7 K0 F500\n");
  ASSERT_EQ(out.moves.size(), 2U);
  const Move& arc = out.moves.back();
  EXPECT_EQ(arc.arc.plane, Plane::yz);
  EXPECT_NEAR(arc.arc.centre[0], 3.0, kTol);  // Y
  EXPECT_NEAR(arc.arc.centre[1], 2.0, kTol);  // Z
}

TEST(GcodeReader, RadiusFormFindsTheCentreOnTheRightSide) {
  // Clockwise from (0,0) to (10,10), R10: the short way round, centre (10,0).
  const Read minor = ok("G2 X10 Y10 R10 F100\n");
  EXPECT_NEAR(minor.moves[0].arc.centre[0], 10.0, 1e-9);
  EXPECT_NEAR(minor.moves[0].arc.centre[1], 0.0, 1e-9);
  // A negative radius: more than half a circle, centre (0,10).
  const Read major = ok("G2 X10 Y10 R-10 F100\n");
  EXPECT_NEAR(major.moves[0].arc.centre[0], 0.0, 1e-9);
  EXPECT_NEAR(major.moves[0].arc.centre[1], 10.0, 1e-9);
  // Counter-clockwise, positive: the other short side.
  const Read ccw = ok("G3 X10 Y10 R10 F100\n");
  EXPECT_NEAR(ccw.moves[0].arc.centre[0], 0.0, 1e-9);
  EXPECT_NEAR(ccw.moves[0].arc.centre[1], 10.0, 1e-9);
}

TEST(GcodeReader, RadiusFormInInchAndInXz) {
  const Read out = ok("G20 G18\nG2 X1 Z1 R1 F10\n");
  const Move& arc = out.moves[0];
  // (Z,X) from (0,0) to (25.4,25.4), clockwise about +Y, R 25.4.
  const double r0 = std::hypot(arc.arc.centre[0], arc.arc.centre[1]);
  const double r1 = std::hypot(arc.arc.centre[0] - 25.4, arc.arc.centre[1] - 25.4);
  EXPECT_NEAR(r0, 25.4, 1e-9);
  EXPECT_NEAR(r1, 25.4, 1e-9);
}

TEST(GcodeReader, SinumerikRadiusIsCr) {
  const Read out = ok("G17 G710\nG2 X10 Y10 CR=10 F100\n", Dialect::sinumerik);
  EXPECT_NEAR(out.moves[0].arc.centre[0], 10.0, 1e-9);
  EXPECT_NEAR(out.moves[0].arc.centre[1], 0.0, 1e-9);
}

TEST(GcodeReader, FullCircleWithTurns) {
  const Read out = ok("G0 X4 Y0\nG2 X4 Y0 I-4 J0 P3 F3000\n");
  const Move& arc = out.moves[1];
  EXPECT_EQ(arc.start, arc.end);
  EXPECT_NEAR(arc.arc.centre[0], 0.0, kTol);
  EXPECT_EQ(arc.arc.extra_turns, 2);
  // A circle written with its centre word only.
  const Read centre_only = ok("G0 X4 Y0\nG2 I-4 F3000\n");
  ASSERT_EQ(centre_only.moves.size(), 2U);
  EXPECT_EQ(centre_only.moves[1].kind, MoveKind::arc);
  EXPECT_EQ(centre_only.moves[1].start, centre_only.moves[1].end);
  EXPECT_EQ(centre_only.moves[1].arc.extra_turns, 0);
  // Sinumerik TURN= counts the extra turns.
  const Read turns = ok("G0 X4 Y0\nG2 X4 Y0 I-4 J0 TURN=2 F3000\n", Dialect::sinumerik);
  EXPECT_EQ(turns.moves[1].arc.extra_turns, 2);
}

TEST(GcodeReader, HelixMovesTheNormalAxis) {
  const Read out = ok("G0 X8 Y0 Z0\nF2000\nG3 X8 Y0 Z-3 I-8 J0 P3\n");
  const Move& helix = out.moves.back();
  EXPECT_EQ(helix.kind, MoveKind::arc);
  EXPECT_NEAR(at(helix.end, Axis::z), -3.0, kTol);
  EXPECT_EQ(helix.arc.extra_turns, 2);
  EXPECT_NEAR(helix.feed.value, 2000.0, kTol);
}

TEST(GcodeReader, AbsoluteArcCentreInLinuxcncG901) {
  const Read out = ok("G90.1\nG0 X10 Y5\nG3 X0 Y15 I0 J5 F100\n");
  EXPECT_NEAR(out.moves[1].arc.centre[0], 0.0, kTol);
  EXPECT_NEAR(out.moves[1].arc.centre[1], 5.0, kTol);
}

TEST(GcodeReader, ArcEndWithinLinuxcncToleranceIsAccepted) {
  // r 10 at the start, 10.02 at the end: within 2 x 0.01 x sqrt 2 mm.
  EXPECT_FALSE(read("G0 X10\nG3 X0 Y10.02 I-10 F100\n").error.has_value());
  // 0.05 mm: off the circle, refused at the motion word.
  expect_refusal("G0 X10\nG3 X0 Y10.05 I-10 F100\n", Refusal::arc_geometry, 2, 1, "G3");
  // Inch: 0.005 in off is refused, 0.002 in (under 0.002 x sqrt 2) accepted.
  expect_refusal("G20\nG0 X1\nG3 X0 Y1.005 I-1 F10\n", Refusal::arc_geometry, 3, 1, "G3");
  EXPECT_FALSE(read("G20\nG0 X1\nG3 X0 Y1.002 I-1 F10\n").error.has_value());
  // An R arc too short for its chord.
  expect_refusal("G2 X10 Y0 R4 F100\n", Refusal::arc_geometry, 1, 11, "R4");
  // An arc with neither centre nor radius.
  expect_refusal("G0 X1\nG2 X2 F100\n", Refusal::arc_geometry, 2, 1, "G2");
  // K in the XY plane.
  expect_refusal("G2 X2 I1 K1 F100\n", Refusal::arc_geometry, 1, 10, "K1");
}

// ---- lathes

TEST(GcodeReader, LinuxcncG7ReadsXAsADiameter) {
  const Read out = ok("G18 G7\nG0 X40 Z-5\nG8\nG0 X40\n");
  ASSERT_EQ(out.moves.size(), 2U);
  EXPECT_NEAR(at(out.moves[0].end, Axis::x), 20.0, kTol);
  EXPECT_NEAR(at(out.moves[0].end, Axis::z), -5.0, kTol);
  EXPECT_NEAR(at(out.moves[1].end, Axis::x), 40.0, kTol);
  // rs274ngc reads X before it runs the G7 of the same block.
  const Read same_block = ok("G7 G0 X40\nG0 X40\n");
  EXPECT_NEAR(at(same_block.moves[0].end, Axis::x), 40.0, kTol);
  EXPECT_NEAR(at(same_block.moves[1].end, Axis::x), 20.0, kTol);
}

TEST(GcodeReader, FanucLatheXIsAlwaysADiameterAndUAnIncrement) {
  const Read out =
      ok("%\nO0002 (GROOVE)\nG21\nG18 G40 G99\nG54\nG00 X40. Z0\nG97 S1000 M03\n"
         "G01 U-2. F0.1\nW-1.\nG00 X50.\nM30\n%\n",
         Dialect::fanuc, MachineKind::lathe);
  ASSERT_EQ(out.moves.size(), 4U);
  EXPECT_NEAR(at(out.moves[0].end, Axis::x), 20.0, kTol);
  EXPECT_NEAR(at(out.moves[1].end, Axis::x), 19.0, kTol);
  EXPECT_EQ(out.moves[1].feed.mode, FeedMode::per_revolution);
  EXPECT_NEAR(out.moves[1].feed.value, 0.1, kTol);
  EXPECT_NEAR(out.moves[1].feed.spindle_rpm, 1000.0, kTol);
  EXPECT_NEAR(at(out.moves[2].end, Axis::z), -1.0, kTol);
  EXPECT_NEAR(at(out.moves[3].end, Axis::x), 25.0, kTol);
  // The same words on a mill: X is X.
  const Read mill = ok("G00 X40.\n", Dialect::fanuc);
  EXPECT_NEAR(at(mill.moves[0].end, Axis::x), 40.0, kTol);
}

TEST(GcodeReader, ArcCentreWordsStayRadiiInDiameterMode) {
  // From diameter 20 (radius 10) at Z0 to diameter 40 (radius 20) at Z10, centre 10 in X
  // above the start (I10 is a radius) and at the start's Z: a quarter circle.
  const Read out = ok("G18 G7\nG0 X20 Z0\nG2 X40 Z10 I10 K0 F100\n");
  const Move& arc = out.moves.back();
  EXPECT_NEAR(arc.arc.centre[0], 0.0, kTol);   // Z
  EXPECT_NEAR(arc.arc.centre[1], 20.0, kTol);  // X radius
}

TEST(GcodeReader, SinumerikDiamonReadsXAsADiameter) {
  const Read out =
      ok("G18 G710 DIAMON\nG0 X40 Z1\nDIAMOF\nG0 X40\n", Dialect::sinumerik, MachineKind::lathe);
  EXPECT_NEAR(at(out.moves[0].end, Axis::x), 20.0, kTol);
  EXPECT_NEAR(at(out.moves[1].end, Axis::x), 40.0, kTol);
  // DIAM90: a diameter in absolute, a radius in incremental.
  const Read diam90 = ok("DIAM90\nG0 X40\nG91 G0 X2\n", Dialect::sinumerik, MachineKind::lathe);
  EXPECT_NEAR(at(diam90.moves[0].end, Axis::x), 20.0, kTol);
  EXPECT_NEAR(at(diam90.moves[1].end, Axis::x), 22.0, kTol);
}

TEST(GcodeReader, LatheStartsInTheZxPlane) {
  const Read out = ok("G0 X10 Z0\nG2 X10 Z10 R5 F100\n", Dialect::linuxcnc, MachineKind::lathe);
  EXPECT_EQ(out.moves.back().arc.plane, Plane::xz);
  EXPECT_EQ(ok("G2 X10 Y10 R10 F100\n").moves[0].arc.plane, Plane::xy);
}

// ---- feeds and the spindle

TEST(GcodeReader, FeedPerRevolutionCarriesTheSpindleSpeed) {
  const Read out = ok("G95\nS1200 M3\nG1 X10 F0.2\nM5\nS800 M4\nG1 X20\n");
  ASSERT_EQ(out.moves.size(), 2U);
  EXPECT_EQ(out.moves[0].feed.mode, FeedMode::per_revolution);
  EXPECT_NEAR(out.moves[0].feed.value, 0.2, kTol);
  EXPECT_NEAR(out.moves[0].feed.spindle_rpm, 1200.0, kTol);
  EXPECT_NEAR(out.moves[0].feed.surface_speed_m_per_min, 0.0, kTol);
  EXPECT_NEAR(out.moves[1].feed.spindle_rpm, 800.0, kTol);
  const Read inch = ok("G20 G95\nS1000 M3\nG1 X1 F0.01\n");
  EXPECT_NEAR(inch.moves[0].feed.value, 0.254, kTol);
}

TEST(GcodeReader, FeedPerRevolutionNeedsATurningSpindle) {
  expect_refusal("G95 F0.1\nG1 X10\n", Refusal::missing_feed, 2, 1, "G1");
  expect_refusal("G95 F0.1 S1000\nG1 X10\n", Refusal::missing_feed, 2, 1, "G1");
  expect_refusal("G95 F0.1 S1000 M3\nM5\nG1 X10\n", Refusal::missing_feed, 3, 1, "G1");
  expect_refusal("G95 F0.1 M3\nG1 X10\n", Refusal::missing_feed, 2, 1, "G1");
}

TEST(GcodeReader, FeedMoveWithoutFIsRefused) {
  expect_refusal("G21\nG1 X10\n", Refusal::missing_feed, 2, 1, "G1");
  expect_refusal("G1 X10 F0\n", Refusal::missing_feed, 1, 1, "G1");
  expect_refusal("G1 X10 F100\nG2 X0 Y0 I-5 F0\n", Refusal::missing_feed, 2, 1, "G2");
  // Modal motion: the first axis word.
  expect_refusal("G0 X1\nG1 F0\nX5\n", Refusal::missing_feed, 3, 1, "X5");
  // Rapids need none.
  EXPECT_FALSE(read("G0 X10\n").error.has_value());
}

TEST(GcodeReader, InverseTimeNeedsFOnEveryFeedBlock) {
  const Read out = ok("G93\nG1 X10 C30 F12.5\nG0 X20\n");
  EXPECT_EQ(out.moves[0].feed.mode, FeedMode::inverse_time);
  EXPECT_NEAR(out.moves[0].feed.value, 12.5, kTol);
  expect_refusal("G93\nG1 X10 F12.5\nG1 X20\n", Refusal::missing_feed, 3, 1, "G1");
  // Inch changes nothing: F is 1/min.
  EXPECT_NEAR(ok("G20 G93\nG1 X1 F4\n").moves[0].feed.value, 4.0, kTol);
}

TEST(GcodeReader, ConstantSurfaceSpeedAndItsClampInEachDialect) {
  // LinuxCNC G96 D: the clamp of that G96.
  const Read linuxcnc = ok("G18 G7 G95\nG96 D2500 S200 M3\nG1 X20 F0.1\n");
  const Feed& lf = linuxcnc.moves[0].feed;
  EXPECT_NEAR(lf.surface_speed_m_per_min, 200.0, kTol);
  EXPECT_NEAR(lf.spindle_rpm, 0.0, kTol);
  EXPECT_NEAR(lf.max_spindle_rpm, 2500.0, kTol);
  // Without D: the machine's limit, also after a G96 with D.
  const Read no_clamp =
      ok("G95\nG96 S200 M3\nG1 X20 F0.1\nG96 D2500 S200\nG1 X30\nG96 S200\nG1 X40\n",
         Dialect::linuxcnc, MachineKind::lathe, 4000.0);
  ASSERT_EQ(no_clamp.moves.size(), 3U);
  EXPECT_NEAR(no_clamp.moves[0].feed.max_spindle_rpm, 4000.0, kTol);
  EXPECT_NEAR(no_clamp.moves[1].feed.max_spindle_rpm, 2500.0, kTol);
  EXPECT_NEAR(no_clamp.moves[2].feed.max_spindle_rpm, 4000.0, kTol);
  // Fanuc lathe G50 S.
  const Read fanuc = ok("G21\nG18 G40 G99\nG50 S1800\nG96 S150 M03\nG01 X20. F0.1\n",
                        Dialect::fanuc, MachineKind::lathe, 4000.0);
  EXPECT_NEAR(fanuc.moves[0].feed.max_spindle_rpm, 1800.0, kTol);
  EXPECT_NEAR(fanuc.moves[0].feed.surface_speed_m_per_min, 150.0, kTol);
  // Sinumerik LIMS=.
  const Read sinumerik = ok("G18 G710 G95 DIAMON\nG96 S86.000 LIMS=1000.000 M3\nG1 X20 F0.1\n",
                            Dialect::sinumerik, MachineKind::lathe);
  EXPECT_NEAR(sinumerik.moves[0].feed.max_spindle_rpm, 1000.0, kTol);
  EXPECT_NEAR(sinumerik.moves[0].feed.surface_speed_m_per_min, 86.0, kTol);
  // G97 returns to constant rpm.
  const Read back = ok("G95\nG96 S200 M3\nG97 S500\nG1 X20 F0.1\n");
  EXPECT_NEAR(back.moves[0].feed.spindle_rpm, 500.0, kTol);
  EXPECT_NEAR(back.moves[0].feed.surface_speed_m_per_min, 0.0, kTol);
}

TEST(GcodeReader, SurfaceSpeedInInchIsFeetPerMinute) {
  const Read out = ok("G20 G95\nG96 D3000 S500 M3\nG1 X1 F0.004\n");
  EXPECT_NEAR(out.moves[0].feed.surface_speed_m_per_min, 152.4, 1e-9);
  EXPECT_NEAR(out.moves[0].feed.value, 0.1016, 1e-12);
}

TEST(GcodeReader, FanucLatheFeedModesAreG98AndG99) {
  const Read out =
      ok("G98\nG01 X10. F100.\nG99 S500 M03\nG01 X20. F0.2\n", Dialect::fanuc, MachineKind::lathe);
  EXPECT_EQ(out.moves[0].feed.mode, FeedMode::units_per_min);
  EXPECT_EQ(out.moves[1].feed.mode, FeedMode::per_revolution);
  // On a mill they are the canned cycles' return levels, with no effect.
  const Read mill = ok("G98\nG01 X10. F100.\n", Dialect::fanuc);
  EXPECT_EQ(mill.moves[0].feed.mode, FeedMode::units_per_min);
}

// ---- path control (machine-time.md 3 M7 and 7)

TEST(GcodeReader, LinuxcncPathModes) {
  const Read out =
      ok("G1 X1 F100\nG61\nG1 X2\nG61.1\nG1 X3\nG64 P0.05\nG1 X4\nG20 G64 P0.002\nG1 X1\n"
         "G64\nG1 X2\n");
  ASSERT_EQ(out.moves.size(), 6U);
  EXPECT_EQ(out.moves[0].path, PathControl::blend);  // the default: G64 without P
  EXPECT_NEAR(out.moves[0].blend_tolerance_mm, 0.0, kTol);
  EXPECT_EQ(out.moves[1].path, PathControl::exact_path);
  EXPECT_EQ(out.moves[2].path, PathControl::exact_stop);
  EXPECT_EQ(out.moves[3].path, PathControl::blend);
  EXPECT_NEAR(out.moves[3].blend_tolerance_mm, 0.05, kTol);
  EXPECT_NEAR(out.moves[4].blend_tolerance_mm, 0.0508, kTol);
  EXPECT_NEAR(out.moves[5].blend_tolerance_mm, 0.0, kTol);
}

TEST(GcodeReader, FanucG61IsExactStopAndG09OneBlock) {
  const Read out =
      ok("G01 X1. F100.\nG09 G01 X2.\nG01 X3.\nG61\nG01 X4.\nG64\nG01 X5.\n", Dialect::fanuc);
  ASSERT_EQ(out.moves.size(), 5U);
  EXPECT_EQ(out.moves[0].path, PathControl::blend);
  EXPECT_EQ(out.moves[1].path, PathControl::exact_stop);
  EXPECT_EQ(out.moves[2].path, PathControl::blend);
  EXPECT_EQ(out.moves[3].path, PathControl::exact_stop);
  EXPECT_EQ(out.moves[4].path, PathControl::blend);
}

TEST(GcodeReader, SinumerikG60IsExactStopAndG641BlendsWithinAdis) {
  const Read out =
      ok("G1 X1 F100\nG60\nG1 X2\nG9 G64 G1 X3\nG641 ADIS=0.1\nG1 X4\nG700\nADIS=0.01\n"
         "G1 X1\n",
         Dialect::sinumerik);
  ASSERT_EQ(out.moves.size(), 5U);
  EXPECT_EQ(out.moves[0].path, PathControl::blend);
  EXPECT_EQ(out.moves[1].path, PathControl::exact_stop);
  EXPECT_EQ(out.moves[2].path, PathControl::exact_stop);  // G9: this block
  EXPECT_EQ(out.moves[3].path, PathControl::blend);
  EXPECT_NEAR(out.moves[3].blend_tolerance_mm, 0.1, kTol);
  EXPECT_NEAR(out.moves[4].blend_tolerance_mm, 0.254, kTol);
}

TEST(GcodeReader, ReferenceSquareReadsAlikeInEveryDialect) {
  const Read linuxcnc = ok("G21 G90 G17 G61.1\nF4000\nG1 X60\nG1 Y60\nG1 X0\nG1 Y0\nM2\n");
  const Read fanuc =
      ok("%\nO0001 (SQUARE)\nG21 G90 G17 G94 G61\nF4000\nG1 X60\nG1 Y60\nG1 X0\n"
         "G1 Y0\nM30\n%\n",
         Dialect::fanuc);
  const Read sinumerik =
      ok("; SQUARE\nG71 G90 G17 G94 G60\nF4000\nG1 X60\nG1 Y60\nG1 X0\nG1 Y0\n"
         "M30\n",
         Dialect::sinumerik);
  for (const Read* other : {&fanuc, &sinumerik}) {
    ASSERT_EQ(other->moves.size(), linuxcnc.moves.size());
    for (std::size_t k = 0; k < linuxcnc.moves.size(); ++k) {
      EXPECT_EQ(other->moves[k].end, linuxcnc.moves[k].end);
      EXPECT_EQ(other->moves[k].path, PathControl::exact_stop);
      EXPECT_NEAR(other->moves[k].feed.value, 4000.0, kTol);
    }
  }
}

// ---- dwells, stops, tool changes

TEST(GcodeReader, DwellInEachDialect) {
  const Read linuxcnc = ok("G1 X1 F100\nG4 P0.5\n");
  ASSERT_EQ(linuxcnc.moves.size(), 2U);
  EXPECT_EQ(linuxcnc.moves[1].kind, MoveKind::dwell);
  EXPECT_NEAR(linuxcnc.moves[1].dwell_s, 0.5, kTol);
  EXPECT_EQ(linuxcnc.moves[1].start, linuxcnc.moves[0].end);
  EXPECT_NEAR(ok("G04 P1500\n", Dialect::fanuc).moves[0].dwell_s, 1.5, kTol);
  // X is the time, not an axis, in a G04 block.
  const Read fanuc = ok("G01 X5. F100.\nG04 X0.461\n", Dialect::fanuc);
  ASSERT_EQ(fanuc.moves.size(), 2U);
  EXPECT_NEAR(fanuc.moves[1].dwell_s, 0.461, kTol);
  EXPECT_NEAR(at(fanuc.moves[1].end, Axis::x), 5.0, kTol);
  EXPECT_NEAR(ok("G04 U2.\n", Dialect::fanuc, MachineKind::lathe).moves[0].dwell_s, 2.0, kTol);
  // Sinumerik: F seconds (not a feed), S spindle revolutions.
  const Read sinumerik = ok("G4 F0.461\nS600 M3\nG4 S2\n", Dialect::sinumerik);
  EXPECT_NEAR(sinumerik.moves[0].dwell_s, 0.461, kTol);
  EXPECT_NEAR(sinumerik.moves[1].dwell_s, 0.2, kTol);
  expect_refusal("G4 F0.5\nG1 X1\n", Refusal::missing_feed, 2, 1, "G1", Dialect::sinumerik);
  expect_refusal("G4 S2\n", Refusal::unsupported_word, 1, 4, "S2", Dialect::sinumerik);
  expect_refusal("G4\n", Refusal::malformed, 1, 1, "G4");
}

TEST(GcodeReader, ToolChangeAndProgramStopsAreUntimedStops) {
  const Read out = ok("G0 X5\nT3 M6\nG0 X6\nM0\nM1\nG0 X7 M0\n");
  std::vector<MoveKind> kinds;
  for (const Move& move : out.moves) kinds.push_back(move.kind);
  EXPECT_EQ(kinds, (std::vector<MoveKind>{MoveKind::rapid, MoveKind::untimed_stop, MoveKind::rapid,
                                          MoveKind::untimed_stop, MoveKind::untimed_stop,
                                          MoveKind::rapid, MoveKind::untimed_stop}));
  EXPECT_EQ(out.moves[1].line, 2U);
  EXPECT_NEAR(at(out.moves[1].start, Axis::x), 5.0, kTol);
  EXPECT_EQ(out.moves[1].start, out.moves[1].end);
  // M0 after the block's motion.
  EXPECT_NEAR(at(out.moves[6].start, Axis::x), 7.0, kTol);
  // A turret lathe changes its tool with the T word itself.
  EXPECT_EQ(ok("T0707\n", Dialect::fanuc, MachineKind::lathe).moves.size(), 1U);
  EXPECT_EQ(ok("T7 D1\n", Dialect::sinumerik, MachineKind::lathe).moves.size(), 1U);
  EXPECT_EQ(ok("T7\n").moves.size(), 0U);
  EXPECT_EQ(ok("T3\nM6\nD1\n", Dialect::sinumerik).moves.size(), 1U);
}

// ---- comments and the program's frame

TEST(GcodeReader, CommentsOfEachDialect) {
  const Read linuxcnc = ok("%\n(NAME)\nG0 X1 (MOVE) Y2 ; REST G0 X9\n; G0 X9\n%\n");
  ASSERT_EQ(linuxcnc.moves.size(), 1U);
  EXPECT_NEAR(at(linuxcnc.moves[0].end, Axis::y), 2.0, kTol);
  EXPECT_EQ(linuxcnc.summary.blocks, 1U);
  const Read fanuc = ok("%\nO0001 (NAME)\n(A COMMENT)\nG00 X1. (MOVE)\n", Dialect::fanuc);
  EXPECT_EQ(fanuc.moves.size(), 1U);
  EXPECT_EQ(fanuc.summary.blocks, 2U);
  const Read sinumerik =
      ok("; NAME\nG0 X1 ; MOVE (X9)\nMSG(\"HELLO (WORLD)\")\nN10 G0 X2\n:20 G0 X3\n",
         Dialect::sinumerik);
  EXPECT_EQ(sinumerik.moves.size(), 3U);
  EXPECT_EQ(sinumerik.summary.blocks, 4U);
  // LinuxCNC refuses nested comments; Sinumerik has no parenthesis comments.
  expect_refusal("G0 X1 (A (B) C)\n", Refusal::malformed, 1, 7, "(A (B)");
  expect_refusal("G0 X1\n(NOTE)\n", Refusal::malformed, 2, 1, "(NOTE)", Dialect::sinumerik);
  expect_refusal("G0 X1 (OPEN\n", Refusal::malformed, 1, 7, "(OPEN");
}

TEST(GcodeReader, ProgramEndStopsReading) {
  const Read m2 = ok("G0 X1\nM2\nG0 X2\n#1=5\n");
  EXPECT_EQ(m2.moves.size(), 1U);
  EXPECT_EQ(m2.summary.blocks, 2U);
  // The motion of the M30 block runs first.
  const Read m30 = ok("G0 X1 M30\nG0 X2\n", Dialect::fanuc);
  EXPECT_EQ(m30.moves.size(), 1U);
  // The closing % ends the program too.
  const Read percent = ok("%\nG0 X1\n%\nG0 X2\n");
  EXPECT_EQ(percent.moves.size(), 1U);
  // Lines with no word are not blocks.
  EXPECT_EQ(ok("\n\n  \nN10\n(C)\n;\n").summary.blocks, 1U);
}

TEST(GcodeReader, FirstLineMovingEachAxis) {
  const Read out = ok("G0 Z5\nG0 X1 Z5\n\nG1 Y2 F100\nG2 X1 Y2 I1 J0\nG1 C90\nG0 X3\n");
  const auto& first = out.summary.first_line_moving;
  EXPECT_EQ(first[index(Axis::z)], 1U);
  EXPECT_EQ(first[index(Axis::x)], 2U);
  EXPECT_EQ(first[index(Axis::y)], 4U);
  EXPECT_EQ(first[index(Axis::c)], 6U);
  EXPECT_EQ(first[index(Axis::a)], 0U);
  EXPECT_EQ(first[index(Axis::b)], 0U);
  // A full circle moves its plane's axes although it ends where it started.
  const Read circle = ok("G2 I5 F100\n");
  EXPECT_EQ(circle.summary.first_line_moving[index(Axis::x)], 1U);
  EXPECT_EQ(circle.summary.first_line_moving[index(Axis::y)], 1U);
  EXPECT_EQ(circle.summary.first_line_moving[index(Axis::z)], 0U);
}

TEST(GcodeReader, BlockDeleteAndLowerCaseAreRead) {
  const Read out = ok("/g0 x1\ng1 y2 f100\n");
  ASSERT_EQ(out.moves.size(), 2U);
  EXPECT_NEAR(at(out.moves[1].end, Axis::y), 2.0, kTol);
}

// ---- refusals: line, column, word

TEST(GcodeReader, ParametersAreRefused) {
  expect_refusal("G21 G90\n#1=5\nG1 X#1 F1000\nM2\n", Refusal::parameter, 2, 1, "#1");
  expect_refusal("G1 X#1 F1000\n", Refusal::parameter, 1, 4, "X#1");
  expect_refusal("G1 X#<depth> F1000\n", Refusal::parameter, 1, 4, "X#<depth>");
  expect_refusal("G0 X10\nR1=5\n", Refusal::parameter, 2, 1, "R1", Dialect::sinumerik);
  expect_refusal("G1 X=R1 F100\n", Refusal::parameter, 1, 4, "X=R1", Dialect::sinumerik);
  expect_refusal("DEF REAL A\n", Refusal::parameter, 1, 1, "DEF REAL A", Dialect::sinumerik);
  expect_refusal("G0 X1\n  #100=1.\n", Refusal::parameter, 2, 3, "#100", Dialect::fanuc);
}

TEST(GcodeReader, ExpressionsAreRefused) {
  expect_refusal("G1 X[1+2] F100\n", Refusal::expression, 1, 4, "X[1+2]");
  expect_refusal("G1 Xsin[30] F100\n", Refusal::expression, 1, 4, "Xsin[30]");
  expect_refusal("G1 X=AC(10) F100\n", Refusal::expression, 1, 4, "X=AC(10)", Dialect::sinumerik);
}

TEST(GcodeReader, SubroutinesAndLoopsAreRefused) {
  expect_refusal("G0 X1\no100 sub\n", Refusal::subroutine_or_loop, 2, 1, "o100");
  expect_refusal("O<probe> call\n", Refusal::subroutine_or_loop, 1, 1, "O<probe>");
  expect_refusal("G0 X1\nM98 P100\n", Refusal::subroutine_or_loop, 2, 1, "M98", Dialect::fanuc);
  expect_refusal("M99\n", Refusal::subroutine_or_loop, 1, 1, "M99", Dialect::fanuc);
  expect_refusal("G0 X1\nGOTO 10\n", Refusal::subroutine_or_loop, 2, 1, "GOTO", Dialect::fanuc);
  expect_refusal("G0 X1\nGOTOF END\n", Refusal::subroutine_or_loop, 2, 1, "GOTOF",
                 Dialect::sinumerik);
  expect_refusal("L10\n", Refusal::subroutine_or_loop, 1, 1, "L10", Dialect::sinumerik);
  expect_refusal("G65 P9010\n", Refusal::subroutine_or_loop, 1, 1, "G65", Dialect::fanuc);
  // A Fanuc O number is the program's header only on its first block.
  expect_refusal("O0001\nG0 X1.\nO0002\n", Refusal::subroutine_or_loop, 3, 1, "O0002",
                 Dialect::fanuc);
}

TEST(GcodeReader, CutterCompensationOnIsRefused) {
  expect_refusal("G40\nG0 X1\nG41 D1 G1 X5 F100\n", Refusal::cutter_compensation, 3, 1, "G41");
  expect_refusal("G42.1 D5\n", Refusal::cutter_compensation, 1, 1, "G42.1");
  expect_refusal("G1 G42 X5 F100\n", Refusal::cutter_compensation, 1, 4, "G42", Dialect::sinumerik);
}

TEST(GcodeReader, CannedCyclesAreRefused) {
  expect_refusal("G0 X1\nG81 Z-5 R1 F100\n", Refusal::canned_cycle, 2, 1, "G81");
  expect_refusal("G83 Z-5 R1 Q1 F100\n", Refusal::canned_cycle, 1, 1, "G83", Dialect::fanuc);
  expect_refusal("G90 X20. Z-10. F0.2\n", Refusal::canned_cycle, 1, 1, "G90", Dialect::fanuc,
                 MachineKind::lathe);
  expect_refusal("G94 X20. Z-10. F0.2\n", Refusal::canned_cycle, 1, 1, "G94", Dialect::fanuc,
                 MachineKind::lathe);
  expect_refusal("G71 U1. R0.5\n", Refusal::canned_cycle, 1, 1, "G71", Dialect::fanuc,
                 MachineKind::lathe);
  expect_refusal("G0 X1\nCYCLE81(10, 0, 2, -5)\n", Refusal::canned_cycle, 2, 1,
                 "CYCLE81(10, 0, 2, -5)", Dialect::sinumerik);
  // G80 cancels and is accepted.
  EXPECT_FALSE(read("G80\nG0 X1\n").error.has_value());
}

TEST(GcodeReader, UnknownAndUntimableWordsAreRefused) {
  expect_refusal("G0 X1\nG28 Z0\n", Refusal::unsupported_word, 2, 1, "G28");
  expect_refusal("G53 G0 Z0\n", Refusal::unsupported_word, 1, 1, "G53");
  expect_refusal("G64 P0.01 Q0.01\n", Refusal::unsupported_word, 1, 11, "Q0.01");
  expect_refusal("M19\n", Refusal::unsupported_word, 1, 1, "M19");
  expect_refusal("G1 X1 E5 F100\n", Refusal::unsupported_word, 1, 7, "E5");
  expect_refusal("G0 X1 U2\n", Refusal::unsupported_word, 1, 7, "U2");
  expect_refusal("G0 X1 I2\n", Refusal::unsupported_word, 1, 7, "I2");
  expect_refusal("G0 X1\nSUPA G0 Z0\n", Refusal::unsupported_word, 2, 1, "SUPA",
                 Dialect::sinumerik);
  expect_refusal("G91 X1.\n", Refusal::unsupported_word, 1, 1, "G91", Dialect::fanuc,
                 MachineKind::lathe);
}

TEST(GcodeReader, MalformedWordsAreRefused) {
  expect_refusal("G1 X1 X2 F100\n", Refusal::malformed, 1, 7, "X2");
  expect_refusal("G1 X F100\n", Refusal::malformed, 1, 4, "X");
  expect_refusal("G0 G1 X1 F100\n", Refusal::malformed, 1, 4, "G1");  // two motions
  expect_refusal("G1 X1 F-100\n", Refusal::malformed, 1, 7, "F-100");
  expect_refusal("X1\n", Refusal::malformed, 1, 1, "X1");  // no motion mode in effect
  expect_refusal("G0 X1\nG80 X2\n", Refusal::malformed, 2, 5, "X2");
  expect_refusal("G2 X2 Y0 R1 I1 F100\n", Refusal::malformed, 1, 10, "R1");
  expect_refusal("G0 X1. ; G0 X2.\n", Refusal::malformed, 1, 10, "G0", Dialect::fanuc);
  expect_refusal("G0 X1 *5\n", Refusal::malformed, 1, 7, "*5");
}

TEST(GcodeReader, ErrorsCountLinesFromOneAcrossCrLf) {
  expect_refusal("G0 X1\r\n\r\n  G41\r\n", Refusal::cutter_compensation, 3, 3, "G41");
}

}  // namespace
}  // namespace cutcalc::domain::machine_time

namespace cutcalc::domain::machine_time {
namespace {

// machine-time.md M8: spindle, coolant and offset words flush the control's queue (LinuxCNC's task
// waits for motion before them): the reader says where, before the block's own motion.
TEST(GcodeReader, SpindleCoolantAndOffsetWordsFlushTheQueueBeforeTheBlocksMotion) {
  std::vector<std::pair<MoveKind, std::size_t>> kinds;
  ReadOptions options;
  const auto result = read_program(
      "G21 G90\nG54\nG0 X1\nS1000 M3\nF100 G1 X2\nM8 G1 X3\nG1 X4\nG43 H1 G0 Z5\nM5 M9\nM2\n",
      options, [&](const Move& move) { kinds.emplace_back(move.kind, move.line); });
  ASSERT_TRUE(std::holds_alternative<ReadSummary>(result));
  const std::vector<std::pair<MoveKind, std::size_t>> expected = {
      {MoveKind::sync, 2},  {MoveKind::rapid, 3}, {MoveKind::sync, 4}, {MoveKind::line, 5},
      {MoveKind::sync, 6},  {MoveKind::line, 6},  {MoveKind::line, 7}, {MoveKind::sync, 8},
      {MoveKind::rapid, 8}, {MoveKind::sync, 9}};
  EXPECT_EQ(kinds, expected);
}

}  // namespace
}  // namespace cutcalc::domain::machine_time
