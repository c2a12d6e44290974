// The reader of rs274's canonical output, on text captured from rs274 (LinuxCNC 2.9) for a
// hand-written program with IJ arcs, a full circle, a clockwise arc and a C axis.

#include "gcode/canon_parser.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using cutcalc::test::gcode::angle_between;
using cutcalc::test::gcode::arc_geometry;
using cutcalc::test::gcode::arc_length_xy;
using cutcalc::test::gcode::arc_point;
using cutcalc::test::gcode::ArcGeometry;
using cutcalc::test::gcode::CanonMotion;
using cutcalc::test::gcode::CanonProgram;
using cutcalc::test::gcode::circle_tangent_at_end;
using cutcalc::test::gcode::circle_tangent_at_start;
using cutcalc::test::gcode::MotionKind;
using cutcalc::test::gcode::norm;
using cutcalc::test::gcode::parse_canon;
using cutcalc::test::gcode::spiral_tangent;
using cutcalc::test::gcode::Vec2;

constexpr const char* kOutput = R"canon(    1 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)
    2 N..... SET_G5X_OFFSET(1, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
    3 N..... SET_G92_OFFSET(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
    4 N..... SET_XY_ROTATION(0.0000)
    5 N..... SET_FEED_REFERENCE(CANON_XYZ)
    6 N..... ON_RESET()
    7 N..... COMMENT("test (with, commas)")
    8 N..... COMMENT("interpreter: feed mode set to units per minute")
    9 N..... SET_FEED_MODE(0, 0)
   10 N..... SET_FEED_RATE(0.0000)
   11 N..... SELECT_PLANE(CANON_PLANE_XY)
   12 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)
   15 N..... STRAIGHT_TRAVERSE(0.0000, 0.0000, 5.0000, 0.0000, 0.0000, 0.0000)
   16 N..... SET_SPINDLE_SPEED(0, 40.0000)
   17 N..... START_SPINDLE_CLOCKWISE(0)
   18 N..... STRAIGHT_TRAVERSE(0.0000, 1.0000, 5.0000, 0.0000, 0.0000, 0.0000)
   20 N..... SET_FEED_MODE(0, 1)
   21 N..... SET_FEED_RATE(0.0000)
   22 N..... SET_FEED_RATE(1.0000)
   23 N..... STRAIGHT_FEED(0.0000, 1.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   24 N..... ARC_FEED(-1.0000, 0.0000, 0.0000, 0.0000, 1, -0.0500, 0.0000, 0.0000, -10.0000)
   25 N..... ARC_FEED(1.0000, 0.0000, 0.0000, 0.0000, 1, -0.0500, 0.0000, 0.0000, -20.5000)
   26 N..... ARC_FEED(0.0000, 1.0000, 0.0000, 0.0000, 1, -0.0500, 0.0000, 0.0000, -20.5000)
   27 N..... ARC_FEED(0.0000, 1.0000, 0.0000, 0.0000, 1, -0.0500, 0.0000, 0.0000, -20.5000)
   28 N..... ARC_FEED(1.0000, 0.0000, 0.0000, 0.0000, -1, -0.0500, 0.0000, 0.0000, -20.5000)
   29 N..... STRAIGHT_FEED(2.0000, 3.0000, -0.0500, 0.0000, 0.0000, -20.5000)
   41 N..... PALLET_SHUTTLE()
   42 N..... PROGRAM_END()
   43 N..... ON_RESET()
)canon";

TEST(CanonParser, ReadsMotionsWithTheirStartPositionsFeedsAndC) {
  const CanonProgram program = parse_canon(kOutput);
  EXPECT_TRUE(program.problems.empty());
  EXPECT_TRUE(program.program_end);
  ASSERT_EQ(program.motions.size(), 9u);
  const auto arcs = program.arcs();
  ASSERT_EQ(arcs.size(), 5u);

  EXPECT_EQ(program.motions[0].kind, MotionKind::traverse);
  EXPECT_EQ(program.motions[2].kind, MotionKind::feed);
  EXPECT_DOUBLE_EQ(program.motions[2].end.z, 0.0);
  EXPECT_DOUBLE_EQ(program.motions[2].feed_rate, 1.0);
  EXPECT_EQ(program.motions[2].feed_mode, 1);

  const CanonMotion& first = arcs[0];
  EXPECT_EQ(first.output_line, 21);  // line of the text (some lines were left out above)
  EXPECT_DOUBLE_EQ(first.start.x, 0.0);
  EXPECT_DOUBLE_EQ(first.start.y, 1.0);
  EXPECT_DOUBLE_EQ(first.start.z, 0.0);
  EXPECT_DOUBLE_EQ(first.end.x, -1.0);
  EXPECT_DOUBLE_EQ(first.end.z, -0.05);
  EXPECT_DOUBLE_EQ(first.end.c, -10.0);
  EXPECT_EQ(first.turn, 1);
  EXPECT_DOUBLE_EQ(arcs[1].start.c, -10.0);
  EXPECT_DOUBLE_EQ(arcs[1].end.c, -20.5);
  EXPECT_EQ(arcs[4].turn, -1);
}

TEST(CanonParser, ArcGeometryFollowsLinuxCncsSweepRules) {
  const auto arcs = parse_canon(kOutput).arcs();
  const ArcGeometry quarter = arc_geometry(arcs[0]);  // (0,1) -> (-1,0) counter-clockwise
  EXPECT_NEAR(quarter.sweep, std::numbers::pi / 2.0, 1e-15);
  EXPECT_NEAR(arc_length_xy(quarter), std::numbers::pi / 2.0, 1e-15);
  const Vec2 middle = arc_point(quarter, 0.5);
  EXPECT_NEAR(middle.x, -std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(middle.y, std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(angle_between(circle_tangent_at_start(quarter), Vec2{-1.0, 0.0}), 0.0, 1e-15);
  EXPECT_NEAR(angle_between(circle_tangent_at_end(quarter), Vec2{0.0, -1.0}), 0.0, 1e-15);

  EXPECT_NEAR(arc_geometry(arcs[1]).sweep, std::numbers::pi, 1e-15);  // half turn
  EXPECT_NEAR(arc_geometry(arcs[3]).sweep, 2.0 * std::numbers::pi,
              1e-15);  // end = start: full circle
  EXPECT_NEAR(arc_geometry(arcs[4]).sweep, -0.5 * std::numbers::pi,
              1e-15);  // clockwise (0,1) -> (1,0)
  EXPECT_NEAR(angle_between(circle_tangent_at_start(arc_geometry(arcs[4])), Vec2{1.0, 0.0}), 0.0,
              1e-15);
}

TEST(CanonParser, SpiralArcsInterpolateTheRadiusLinearly) {
  CanonMotion arc;
  arc.kind = MotionKind::arc;
  arc.start = {1.0, 0.0, 0.0, 0, 0, 0};
  arc.end = {0.0, 1.001, -0.1, 0, 0, 0};
  arc.turn = 1;
  const ArcGeometry g = arc_geometry(arc);
  EXPECT_NEAR(g.sweep, std::numbers::pi / 2.0, 1e-15);
  EXPECT_NEAR(norm(arc_point(g, 0.5)), 1.0005, 1e-15);
  EXPECT_NEAR(arc_length_xy(g), std::numbers::pi / 2.0 * 1.0005, 1e-15);
  // The spiral tangent leans outwards by atan(dr / (r dphi)).
  const double lean = angle_between(circle_tangent_at_start(g), spiral_tangent(g, 0.0));
  EXPECT_NEAR(lean, -std::atan(0.001 / (std::numbers::pi / 2.0)), 1e-12);
}

TEST(CanonParser, RemovesWorkOffsetsAndFlagsWhatItCannotCheck) {
  const CanonProgram program = parse_canon(
      "1 N..... SET_G5X_OFFSET(1, 10.0000, 20.0000, 1.0000, 0.0000, 0.0000, 0.0000)\n"
      "2 N..... SELECT_PLANE(CANON_PLANE_XZ)\n"
      "3 N..... STRAIGHT_TRAVERSE(10.0000, 21.0000, 6.0000, 0.0000, 0.0000, 0.0000)\n"
      "4 N..... ARC_FEED(9.0000, 20.0000, 10.0000, 20.0000, 1, 1.0000, 0.0000, 0.0000, 0.0000)\n"
      "5 N..... ARC_FEED(oops)\n");
  ASSERT_EQ(program.motions.size(), 2u);
  EXPECT_DOUBLE_EQ(program.motions[0].end.y, 1.0);
  EXPECT_DOUBLE_EQ(program.motions[0].end.z, 5.0);
  EXPECT_DOUBLE_EQ(program.motions[1].centre.x, 0.0);
  EXPECT_DOUBLE_EQ(program.motions[1].end.x, -1.0);
  EXPECT_EQ(program.problems.size(), 2u);  // the XZ plane and the unreadable arc
  EXPECT_FALSE(program.program_end);
}

}  // namespace
