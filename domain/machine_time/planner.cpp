#include "domain/machine_time/planner.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "domain/machine_time/blend.h"
#include "domain/machine_time/segment_builder.h"
#include "domain/machine_time/trapezoid.h"

namespace cutcalc::domain::machine_time {
namespace {

// A segment that ends at rest ends inside a servo period; the next one starts with the next
// period (tpCheckEndCondition removes it, tpActivateSegment runs the next one a cycle later).
constexpr double kStopPeriods = 0.5;

// After a queue flush (a dwell, a spindle or coolant word) the control's task loop sends the
// next moves; the oracle measured a few milliseconds more than the dwell (machine-time.md 5).
constexpr double kFlushLatencyS = 0.0035;

// tcClampVelocityByLength (M6): no faster than the whole segment in `period`.
void clamp_by_length(Segment& segment, double period) {
  const double per_period = segment.target / period;
  if (per_period < segment.maxvel) {
    segment.maxvel = per_period;
    if (per_period < segment.reqvel) {
      if (segment.limit == Limit::feed || segment.limit == Limit::axis_velocity) {
        segment.limit = Limit::segment_length;
      }
      segment.too_short = !segment.rapid;
    }
  }
}

void remove_kink(Segment& prev, Segment& next) {
  prev.kink_vel = -1.0;
  prev.kink_accel_reduce = 0.0;
  next.kink_accel_reduce_prev = 0.0;
}

enum class BlendChoice { none, parabolic, tangent, arc };

// tpChooseBestBlend: the blend that keeps the most speed through the corner.
BlendChoice choose_best_blend(Segment& prev, Segment& next, const Segment* arc,
                              const Machine& machine) {
  if (prev.term == Termination::exact || prev.term == Termination::stop) {
    return BlendChoice::none;
  }
  const double perf_parabolic = parabolic_blend(prev, next, max_target_velocity(prev, machine),
                                                max_target_velocity(next, machine))
                                    .v_net /
                                2.0;
  const double perf[3] = {perf_parabolic, prev.kink_vel, arc ? arc->maxvel : 0.0};
  int best = 0;
  for (int i = 1; i < 3; ++i) {
    if (perf[i] > perf[best]) {
      best = i;
    }
  }
  switch (best) {
    case 0:
      remove_kink(prev, next);
      prev.term = Termination::parabolic;
      next.blend_prev = true;
      return BlendChoice::parabolic;
    case 1:
      prev.term = Termination::tangent;
      next.blend_prev = false;
      return BlendChoice::tangent;
    default:
      remove_kink(prev, next);
      return BlendChoice::arc;
  }
}

}  // namespace

Planner::Planner(const Machine& machine, RunSink sink)
    : machine_(machine), sink_(std::move(sink)) {}

double Planner::target_velocity(const Segment& segment) const {
  return real_target_velocity(segment, machine_);
}

void Planner::add(const Move& move) {
  switch (move.kind) {
    case MoveKind::dwell:
      flush();
      if (move.dwell_s > 0.0) {
        Run pause;
        pause.line = move.line;
        pause.motion = false;
        pause.dwell = true;
        pause.start_s = clock_s_;
        pause.duration_s = move.dwell_s;
        pause.advance_s = move.dwell_s;
        sink_(pause);
        clock_s_ += move.dwell_s;
      }
      return;
    case MoveKind::untimed_stop:
    case MoveKind::sync:
      flush();
      return;
    case MoveKind::rapid:
    case MoveKind::line:
    case MoveKind::arc:
      break;
  }
  if (std::optional<Segment> segment = build_segment(move, machine_)) {
    enqueue(std::move(*segment));
  }
}

void Planner::enqueue(Segment segment) {
  if (flushed_ && started_) {
    Run pause;
    pause.line = segment.line;
    pause.motion = false;
    pause.start_s = clock_s_;
    pause.duration_s = kFlushLatencyS;
    pause.advance_s = kFlushLatencyS;
    sink_(pause);
    clock_s_ += kFlushLatencyS;
  }
  flushed_ = false;
  clamp_by_length(segment, machine_.servo_period_s);
  if (!queue_.empty()) {
    Segment* prev = &queue_.back();
    // handleModeChange: a rapid never blends with a feed move.
    if (prev->rapid != segment.rapid) {
      prev->term = Termination::stop;
      segment.blend_prev = false;
    }
    const bool prev_consumed = handle_blend(*prev, segment);
    if (!prev_consumed) {
      finalize(*prev);
    }
  }
  queue_.push_back(std::move(segment));
  optimize();
  // A segment further back than the optimisation reaches can no longer change.
  while (queue_.size() > static_cast<std::size_t>(kOptimizationDepth) + 3) {
    execute_front();
  }
}

bool Planner::handle_blend(Segment& prev, Segment& next) {
  if (setup_tangent(prev, next, machine_) != TangentCheck::corner) {
    return false;
  }
  if (std::optional<BlendArc> blend = make_blend_arc(prev, next, machine_)) {
    if (choose_best_blend(prev, next, &blend->arc, machine_) == BlendChoice::arc) {
      const bool consume = blend->consume;
      if (consume) {
        // prev lives on inside the arc: its block's nominal time and warnings go with it.
        blend->arc.nominal_s += prev.nominal_s;
        blend->arc.feed_capped = blend->arc.feed_capped || prev.feed_capped;
        blend->arc.too_short = blend->arc.too_short || prev.too_short;
        queue_.pop_back();
      } else {
        prev.target -= blend->trim;
        prev.term = Termination::tangent;
      }
      next.target = std::max(next.target - blend->trim, 0.0);
      next.blend_prev = false;
      queue_.push_back(std::move(blend->arc));
      return consume;
    }
  }
  choose_best_blend(prev, next, nullptr, machine_);
  return false;
}

void Planner::finalize(Segment& segment) const {
  if (segment.finalized) {
    return;
  }
  clamp_by_length(segment, machine_.servo_period_s);
  if (segment.shape == Shape::arc) {
    // pmCircleActualMaxVel (M5): the normal acceleration v^2 / r takes at most sqrt(3)/2 of a.
    const double a = overall_accel(segment);
    const double radius = std::max(segment.effective_radius, kDoubleFuzz);
    const double a_n_cutoff = kNormalAccelRatio * a;
    const double a_n_vmax = segment.maxvel * segment.maxvel / radius;
    if (a_n_vmax > a_n_cutoff) {
      segment.maxvel = std::sqrt(a_n_cutoff * radius);
      segment.acc_ratio_tan = kAccRatioTangential;
      if (segment.maxvel < segment.reqvel && segment.limit == Limit::feed) {
        segment.limit = Limit::arc;
      }
    } else if (a > 0.0) {
      segment.acc_ratio_tan = std::sqrt(1.0 - (a_n_vmax / a) * (a_n_vmax / a));
    }
  }
  segment.finalized = true;
}

void Planner::optimize() {
  const std::size_t len = queue_.size();
  int hit_peaks = 0;
  bool hit_non_tangent = false;
  for (std::size_t x = 1; x < static_cast<std::size_t>(kOptimizationDepth) + 2; ++x) {
    if (x + 1 > len) {
      return;
    }
    Segment& tc = queue_[len - x];
    Segment& prev = queue_[len - x - 1];
    if (prev.term != Termination::tangent) {
      if (hit_non_tangent) {
        return;
      }
      hit_non_tangent = true;
      continue;
    }
    if (!tc.finalized) {
      // The last segment may still lose half its length to a blend: assume it stops at half.
      const double triangle = std::sqrt(tangential_accel(tc) * tc.target);
      prev.finalvel = std::min(prev.maxvel, std::min(triangle, max_target_velocity(tc, machine_)));
      if (prev.kink_vel >= 0.0) {
        prev.finalvel = std::min(prev.finalvel, prev.kink_vel);
      }
      tc.finalvel = 0.0;
    } else {
      // tpComputeOptimalVelocity: the fastest prev may end at and still let tc reach its end.
      double vs_back =
          std::sqrt(tc.finalvel * tc.finalvel + 2.0 * tangential_accel(tc) * tc.target);
      double vf_limit = std::min(tc.maxvel, prev.maxvel);
      if (prev.kink_vel >= 0.0) {
        vf_limit = std::min(vf_limit, prev.kink_vel);
      }
      if (vs_back >= vf_limit) {
        vs_back = vf_limit;
        prev.at_max = true;
      }
      prev.finalvel = vs_back;
      clamp_by_length(tc, machine_.servo_period_s * kMinSegmentCycles);
    }
    if (tc.at_max && ++hit_peaks > kOptimizationCutoffPeaks) {
      return;
    }
  }
}

void Planner::execute_front() {
  Segment tc = queue_.take_front();
  const Segment* next = queue_.empty() ? nullptr : &queue_.front();
  const double v_target = target_velocity(tc);
  const double accel = tangential_accel(tc);
  double v_final = 0.0;
  if (tc.term == Termination::tangent && next != nullptr) {
    v_final = std::min({tc.finalvel, v_target, target_velocity(*next)});
  }
  const double v_start = blending_in_ ? 0.0 : velocity_;

  Trapezoid profile;
  // tpActivateSegment: a short tangent feed segment ramps its speed linearly to the next one's.
  const double ramp_denominator = v_start + std::min(tc.finalvel, v_target);
  const bool ramp = tc.term == Termination::tangent && !tc.rapid && ramp_denominator > 0.0 &&
                    2.0 * tc.target / ramp_denominator < 1.0 / kRampFrequencyHz &&
                    v_start + v_final > 0.0 &&
                    std::fabs(v_final * v_final - v_start * v_start) <= 2.0 * accel * tc.target;
  if (ramp) {
    profile.duration_s = 2.0 * tc.target / (v_start + v_final);
    profile.v_peak = std::max(v_start, v_final);
    profile.v_end = v_final;
    profile.accel_s = v_final > v_start ? profile.duration_s : 0.0;
  } else {
    profile = plan_trapezoid(tc.target, v_start, v_final, std::max(v_target, v_start), accel);
  }

  // tpDoParabolicBlending: the next segment starts once this one slows below its blend velocity.
  double overlap_s = 0.0;
  if (tc.term == Termination::parabolic && next != nullptr && accel > 0.0) {
    const ParabolicBlend blend = parabolic_blend(tc, *next, v_target, target_velocity(*next));
    const double decel_s = std::max(profile.duration_s - profile.accel_s - profile.cruise_s, 0.0);
    overlap_s = std::clamp(std::min(blend.v_this, profile.v_peak) / accel, 0.0, decel_s);
  }

  Run run;
  run.line = tc.line;
  run.rapid = tc.rapid;
  run.start_s = clock_s_;
  run.duration_s = profile.duration_s;
  run.v_start = v_start;
  run.v_peak = profile.v_peak;
  run.v_end = profile.v_end;
  run.accel_s = profile.accel_s;
  run.cruise_s = profile.cruise_s;
  run.length = tc.target;
  run.nominal_s = tc.nominal_s;
  run.pure_rotary = tc.pure_rotary;
  run.limit = tc.limit;
  run.feed_capped = tc.feed_capped;
  run.too_short = tc.too_short;
  if (run.limit == Limit::feed) {
    if (tc.shape == Shape::blend_arc || overlap_s > 0.0) {
      run.limit = Limit::blend;
    } else if (profile.v_peak < v_target * (1.0 - 1e-9)) {
      run.limit = Limit::acceleration;
    } else if (profile.accel_s > 0.0 || profile.v_end < profile.v_peak) {
      run.limit = Limit::acceleration;
    }
  }
  started_ = true;
  clock_s_ += profile.duration_s - overlap_s;
  blending_in_ = overlap_s > 0.0;
  if (tc.term == Termination::tangent && next != nullptr) {
    velocity_ = profile.v_end;
  } else {
    velocity_ = 0.0;
    if (!blending_in_) {
      clock_s_ += kStopPeriods * machine_.servo_period_s;
    }
  }
  run.advance_s = clock_s_ - run.start_s;
  sink_(run);
}

void Planner::flush() {
  while (!queue_.empty()) {
    execute_front();
  }
  velocity_ = 0.0;
  blending_in_ = false;
  flushed_ = true;
}

void Planner::finish() {
  flush();
  flushed_ = false;
}

}  // namespace cutcalc::domain::machine_time
