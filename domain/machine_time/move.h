#pragma once
// The motion of a program as a control sees it (spec machine-time.md sections 2 and 4): what the
// G-code reader (gcode_reader.h) produces and the planner (planner.h) times. Machine units: mm for
// X, Y, Z; degrees for A, B, C; minutes for feeds; every offset already applied, X a radius on a
// lathe whatever the program's diameter mode.

#include <array>
#include <cstddef>
#include <cstdint>

namespace cutcalc::domain::machine_time {

enum class Axis : std::uint8_t { x, y, z, a, b, c };
inline constexpr std::size_t kAxisCount = 6;
using AxisVector = std::array<double, kAxisCount>;  // indexed by Axis

constexpr std::size_t index(Axis axis) { return static_cast<std::size_t>(axis); }
constexpr bool is_rotary(std::size_t axis_index) { return axis_index >= 3; }

enum class MoveKind : std::uint8_t {
  rapid,         // G0
  line,          // G1
  arc,           // G2/G3, a helix when the normal axis moves too
  dwell,         // G4: dwell_s
  untimed_stop,  // M0, M1, M6: the control waits for someone; warning untimed_stop (M8)
  sync,          // spindle, coolant, work or tool offset words: the control finishes the queued
                 // motion before it goes on (no blending across), and takes no time itself
};

enum class PathControl : std::uint8_t {
  exact_stop,  // LinuxCNC G61.1 (Fanuc G61? see the reader; Sinumerik G60 / G9)
  exact_path,  // LinuxCNC G61
  blend,       // LinuxCNC G64 [P tolerance]
};

enum class FeedMode : std::uint8_t {
  units_per_min,  // G94: value mm/min (or deg/min on a rotary-only move)
  inverse_time,   // G93: the block takes 1 / value minutes
  per_revolution  // G95: value mm per spindle revolution
};

enum class Plane : std::uint8_t { xy, xz, yz };  // G17, G18, G19

struct Feed {
  FeedMode mode = FeedMode::units_per_min;
  double value = 0.0;  // F converted to mm (per min or per rev) or 1/min
  // The spindle when the move starts (per_revolution): rev/min, or constant surface speed.
  double spindle_rpm = 0.0;              // G97 S (0: spindle stopped)
  double surface_speed_m_per_min = 0.0;  // G96 S in m/min; 0: G97 (constant rpm)
  double max_spindle_rpm = 0.0;          // G96 clamp (G50 S, D, LIMS, or the machine's); 0: none
};

struct ArcGeometry {
  Plane plane = Plane::xy;
  std::array<double, 2> centre{};  // in the plane's two axes (G17: X, Y; G18: Z, X; G19: Y, Z)
  bool clockwise = false;          // G2, seen from the plane's positive normal
  int extra_turns = 0;             // P - 1
};

struct Move {
  MoveKind kind = MoveKind::line;
  std::size_t line = 0;  // 1-based line of the block in the program text
  AxisVector start{};
  AxisVector end{};
  ArcGeometry arc;  // kind == arc
  Feed feed;        // kind == line / arc
  PathControl path = PathControl::blend;
  double blend_tolerance_mm = 0.0;  // G64 P; 0: no tolerance
  double dwell_s = 0.0;             // kind == dwell
};

}  // namespace cutcalc::domain::machine_time
