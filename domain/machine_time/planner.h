#pragma once
// The time a control takes to run a stream of moves (spec machine-time.md section 3, M2-M8):
// LinuxCNC 2.9's trajectory planner (src/emc/tp/tp.c) as queue operations and closed-form
// trapezoids instead of servo cycles. Segments enter a look-ahead queue as LinuxCNC's tpAddLine /
// tpAddCircle add them (tangency, blend arcs, parabolic blends, finalisation, the backward
// "rising tide" optimisation); a segment leaves the queue, timed, once no later segment can change
// it. Memory: the queue, never the whole program.

#include <cstddef>
#include <functional>

#include "domain/machine_time/machine.h"
#include "domain/machine_time/move.h"
#include "domain/machine_time/segment.h"
#include "domain/machine_time/segment_ring.h"

namespace cutcalc::domain::machine_time {

// One timed piece of the run, in the order they start: a segment's velocity profile (a trapezoid:
// accelerate, cruise, decelerate) or a pause (dwell, or the control finishing its queue).
struct Run {
  std::size_t line = 0;
  bool rapid = false;
  bool motion = true;    // false: a dwell or a queue flush, velocity 0
  bool dwell = false;    // a G4 pause (else a flush's latency)
  double start_s = 0.0;  // from the first motion
  double duration_s = 0.0;
  double advance_s = 0.0;  // how far it moved the clock (less than duration_s when the next
                           // segment starts inside a parabolic blend)
  double v_start = 0.0;    // units/s
  double v_peak = 0.0;
  double v_end = 0.0;
  double accel_s = 0.0;   // time spent reaching v_peak
  double cruise_s = 0.0;  // time at v_peak; the rest decelerates to v_end
  double length = 0.0;
  double nominal_s = 0.0;  // the block's share of T_n carried by this run
  Limit limit = Limit::feed;
  bool pure_rotary = false;
  bool feed_capped = false;
  bool too_short = false;
};

using RunSink = std::function<void(const Run&)>;

// The planner's fixed settings, LinuxCNC 2.9's defaults ([TRAJ] ARC_BLEND_*).
inline constexpr int kOptimizationDepth = 50;       // ARC_BLEND_OPTIMIZATION_DEPTH
inline constexpr int kBlendGapCycles = 4;           // ARC_BLEND_GAP_CYCLES
inline constexpr double kRampFrequencyHz = 100.0;   // ARC_BLEND_RAMP_FREQ
inline constexpr double kTangentKinkRatio = 0.1;    // ARC_BLEND_KINK_RATIO
inline constexpr double kMinSegmentCycles = 1.02;   // TP_MIN_SEGMENT_CYCLES
inline constexpr int kOptimizationCutoffPeaks = 4;  // TP_OPTIMIZATION_CUTOFF
inline constexpr double kAccRatioTangential = 0.5;  // BLEND_ACC_RATIO_TANGENTIAL
static_assert(kOptimizationDepth + 5 < 64, "the look-ahead queue's ring holds the window");

class Planner {
 public:
  Planner(const Machine& machine, RunSink sink);

  // A move of the reader (rapid, line, arc, dwell, stop, sync). Moves of zero length are skipped,
  // as LinuxCNC drops them.
  void add(const Move& move);
  // Runs what is still queued, to rest (the program's end).
  void finish();

  [[nodiscard]] double elapsed_s() const { return clock_s_; }

 private:
  void enqueue(Segment segment);
  void flush();
  void execute_front();
  void optimize();
  // Returns whether prev was consumed by a blend arc (and so left the queue).
  bool handle_blend(Segment& prev, Segment& next);
  void finalize(Segment& segment) const;
  [[nodiscard]] double target_velocity(const Segment& segment) const;

  Machine machine_;
  RunSink sink_;
  // At most kOptimizationDepth + 3 segments stay queued, plus the one being added and its blend
  // arc.
  SegmentRing<64> queue_;
  double clock_s_ = 0.0;      // where the next segment starts
  double velocity_ = 0.0;     // the speed the next segment starts at (tangent joins)
  bool blending_in_ = false;  // the next segment starts inside a parabolic blend
  bool started_ = false;      // a motion ran
  bool flushed_ = false;      // the queue ran empty for a dwell, a stop or a sync word
};

}  // namespace cutcalc::domain::machine_time
