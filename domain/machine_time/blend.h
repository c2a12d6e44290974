#pragma once
// What happens at the corner between two queued segments in LinuxCNC 2.9 (spec machine-time.md
// M7): the tangency check with its "kink" (tp.c tpSetupTangent), the blend arc that replaces a
// corner (blendmath.c blendInit3FromLineLine, blendParamKinematics, blendComputeParameters,
// blendCheckConsume), and the parabolic blend's velocity (tp.c tpComputeBlendVelocity).

#include <optional>

#include "domain/machine_time/machine.h"
#include "domain/machine_time/segment.h"

namespace cutcalc::domain::machine_time {

enum class TangentCheck {
  refused,  // no blending at all (rotary motion, an exact stop, a reversal)
  tangent,  // close enough to tangent: run through at the kink velocity
  corner,   // a real corner: a blend arc or a parabolic blend may take it
};

// tpSetupTangent: may set prev's termination and both segments' kink properties.
TangentCheck setup_tangent(Segment& prev, Segment& next, const Machine& machine);

struct BlendArc {
  Segment arc;
  double trim = 0.0;     // taken off the end of prev and the start of next
  bool consume = false;  // prev is too short to keep: the arc takes what is left of it
};

// The blend arc between prev and next (both in G64, neither rotary), or nullopt when none fits.
std::optional<BlendArc> make_blend_arc(const Segment& prev, const Segment& next,
                                       const Machine& machine);

// The segment's acceleration along its path (tcGetOverallMaxAccel, tcGetTangentialMaxAccel).
double overall_accel(const Segment& segment);
double tangential_accel(const Segment& segment);

// The largest velocity the segment may be planned for (tpGetMaxTargetVel with no feed override),
// and the one it runs at (tpGetRealTargetVel: the feed, or the spindle's feed when synchronised).
double max_target_velocity(const Segment& segment, const Machine& machine);
double real_target_velocity(const Segment& segment, const Machine& machine);

// tpComputeBlendVelocity: the velocities below which a parabolic blend starts; `net` is the
// equivalent velocity through the corner (estimateParabolicBlendPerformance).
struct ParabolicBlend {
  double v_this = 0.0;
  double v_next = 0.0;
  double v_net = 0.0;
};
ParabolicBlend parabolic_blend(const Segment& segment, const Segment& next, double target_this,
                               double target_next);

// The peak velocity reachable over `distance` at `accel` (findVPeak: stop at half way).
double triangle_velocity(const Segment& segment);

}  // namespace cutcalc::domain::machine_time
