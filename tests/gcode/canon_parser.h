#pragma once
// Reads the canonical commands printed by LinuxCNC's rs274 (one per line, e.g.
// `   24 N..... ARC_FEED(-1.0000, 0.0000, 0.0000, 0.0000, 1, -0.0500, 0.0000, 0.0000, -10.0000)`)
// into the motions of the program in the hole frame (program coordinates: the G5x and G92 offsets
// that rs274 reports are removed), tracking the current position, feed rate and feed mode.

#include <string>
#include <string_view>
#include <vector>

#include "gcode/vec2.h"

namespace cutcalc::test::gcode {

struct CanonPose {
  double x = 0.0, y = 0.0, z = 0.0, a = 0.0, b = 0.0, c = 0.0;
  [[nodiscard]] Vec2 xy() const { return {x, y}; }
};

enum class MotionKind { traverse, feed, arc };

struct CanonMotion {
  MotionKind kind = MotionKind::feed;
  int output_line = 0;  // 1-based line of rs274's output
  CanonPose start;      // the position before the motion
  CanonPose end;
  Vec2 centre;           // arcs: the centre in the XY plane
  int turn = 0;          // arcs: +k counter-clockwise (G3), -k clockwise (G2); |k| - 1 extra turns
  double feed_rate = 0;  // the last SET_FEED_RATE
  int feed_mode = 0;     // the last SET_FEED_MODE: 0 units per minute (G94), 1 per revolution (G95)
};

struct CanonProgram {
  std::vector<CanonMotion> motions;
  std::vector<std::string> problems;  // what the checker cannot interpret (plane, units, rotation)
  bool program_end = false;           // PROGRAM_END() seen
  [[nodiscard]] std::vector<CanonMotion> arcs() const;
};

CanonProgram parse_canon(std::string_view output);

// How LinuxCNC moves along an ARC_FEED: angle linear from the start angle over `sweep`, radius
// linear from |S - C| to |E - C| (a spiral when they differ), Z linear (helix).
struct ArcGeometry {
  Vec2 centre;
  double start_angle = 0.0;
  double sweep = 0.0;  // signed, radians; counter-clockwise positive
  double start_radius = 0.0;
  double end_radius = 0.0;
  double start_z = 0.0;
  double end_z = 0.0;
};

ArcGeometry arc_geometry(const CanonMotion& arc);
// f in [0, 1] along the arc.
Vec2 arc_point(const ArcGeometry& arc, double f);
// XY length as LinuxCNC interpolates it (spec P23): |sweep| (r_start + r_end) / 2.
double arc_length_xy(const ArcGeometry& arc);
// Unit tangents in the direction of motion. "Circle" tangents are perpendicular to point - centre
// (the spec's kink definition); the spiral tangent adds the radial term (r_end - r_start) / sweep.
Vec2 circle_tangent_at_start(const ArcGeometry& arc);
Vec2 circle_tangent_at_end(const ArcGeometry& arc);
Vec2 spiral_tangent(const ArcGeometry& arc, double f);

}  // namespace cutcalc::test::gcode
