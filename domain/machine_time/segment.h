#pragma once
// One segment of the trajectory planner's queue (spec machine-time.md section 3; LinuxCNC 2.9's
// TC_STRUCT, src/emc/tp/tc_types.h): a programmed line or arc, or a blend arc the planner put
// between two of them. Lengths in mm (degrees for a rotary-only line), velocities in units/s.

#include <cstddef>
#include <cstdint>

#include "domain/machine_time/vec3.h"

namespace cutcalc::domain::machine_time {

// LinuxCNC 2.9's constants that more than one step of the planner uses (segment_builder.cpp,
// blend.cpp, planner.cpp).
inline constexpr double kPositionEpsilon = 1e-12;  // TP_POS_EPSILON: shorter segments are dropped
inline constexpr double kDoubleFuzz = 2.2204460492503131e-16;  // DOUBLE_FUZZ
inline constexpr double kNormalAccelRatio =
    0.86602540378443860;  // sqrt(3)/2, BLEND_ACC_RATIO_NORMAL

enum class Shape : std::uint8_t { line, arc, blend_arc };

// How a segment ends (TC_TERM_COND_*).
enum class Termination : std::uint8_t {
  stop,       // G61.1, a rapid next to a feed move, a sharp reversal: rest at the end
  exact,      // G61: rest at the end, the corner kept
  parabolic,  // G64 with no blend arc: the next segment starts while this one slows down
  tangent,    // runs into the next segment at speed
};

// What held a block's speed down, for slowest_blocks (section 6).
enum class Limit : std::uint8_t {
  feed,            // nothing but the programmed feed and the accelerations it needs
  axis_velocity,   // an axis's maximum velocity (or the trajectory's) is below the feed
  acceleration,    // the segment is too short to reach its feed
  arc,             // the arc's normal acceleration caps the speed (M5)
  segment_length,  // one segment per servo period (M6)
  blend,           // a corner in G64 slowed down (blend arc or parabolic blend)
};

struct Segment {
  Shape shape = Shape::line;
  bool rapid = false;
  bool rotary = false;  // A, B or C move: no tangency check, no blend arc (tcRotaryMotionCheck)
  bool pure_rotary = false;  // only rotary axes move: degrees, no trajectory maximum
  bool synced = false;       // feed per revolution (TC_SYNC_VELOCITY): the feed follows the spindle
  std::size_t line = 0;      // the block it comes from (a blend arc: the block before it)

  double target = 0.0;            // length still to run
  double nominal_length = 0.0;    // as programmed
  double reqvel = 0.0;            // the programmed feed, capped by the axes
  double maxvel = 0.0;            // the axes' cap (and later the arc and length caps)
  double maxaccel = 0.0;          // along the path
  double feed_cap = 0.0;          // the programmed feed alone (0 for rapids), for the reports
  double nominal_velocity = 0.0;  // M1: the feed capped by the axes (no arc or length caps)

  Termination term = Termination::parabolic;
  double tolerance = 0.0;   // G64 P; 0: none
  bool blend_prev = false;  // the previous segment blends parabolically into this one
  double kink_vel = -1.0;
  double kink_accel_reduce = 0.0;
  double kink_accel_reduce_prev = 0.0;
  double acc_ratio_tan = 0.5;  // BLEND_ACC_RATIO_TANGENTIAL until an arc is finalized
  bool finalized = false;
  double finalvel = 0.0;
  bool at_max = false;  // TC_OPTIM_AT_MAX
  bool consumed_by_blend = false;

  // Geometry: unit tangents at both ends (xyz), the end point, and for arcs the curvature.
  Vec3 start_tangent;
  Vec3 end_tangent;
  Vec3 end_point;
  Vec3 normal;                    // arcs: the unit axis the arc turns about
  double effective_radius = 0.0;  // pmCircleEffectiveMinRadius (arcs)
  double arc_radius = 0.0;        // for blend arcs and arcs

  Limit limit = Limit::feed;  // the strongest cap met so far
  double nominal_s = 0.0;     // the block's nominal time T_n (M1), on its first segment only
  bool feed_capped = false;   // an axis (or the trajectory maximum) is slower than F: warning
  bool too_short = false;     // one servo period caps the speed below the feed: warning
};

}  // namespace cutcalc::domain::machine_time
