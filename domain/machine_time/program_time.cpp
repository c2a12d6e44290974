#include "domain/machine_time/program_time.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "domain/machine_time/planner.h"

namespace cutcalc::domain::machine_time {
namespace {

using program::Warning;
using program::WarningCode;

// A block that loses less than this lost nothing (rounding of sums of times).
constexpr double kNothingLostS = 1e-6;

// How often something happened and where first: one warning for all of them.
struct Occurrences {
  std::size_t count = 0;
  std::size_t first_line = 0;
  void add(std::size_t line) {
    if (count++ == 0) first_line = line;
  }
};

std::string where(const Occurrences& o) {
  std::string text = std::to_string(o.count) + (o.count == 1 ? " block" : " blocks");
  text += " (first at line " + std::to_string(o.first_line) + ")";
  return text;
}

// Sums the runs as the planner times them: the split, the lengths, the blocks that lose the most.
class Accounting {
 public:
  void add(const Run& run) {
    if (!run.motion) {
      if (run.dwell) {
        time_.dwell_s += run.advance_s;
        time_.nominal_s += run.duration_s;
      }
      return;
    }
    time_.nominal_s += run.nominal_s;
    if (run.rapid) {
      time_.rapid_s += run.advance_s;
      time_.rapid_length_mm += run.pure_rotary ? 0.0 : run.length;
    } else if (!run.pure_rotary) {
      time_.feed_length_mm += run.length;
    }
    if (run.pure_rotary) {
      time_.rotary_deg += run.length;
    }
    if (run.feed_capped) feed_capped_.add(run.line);
    if (run.too_short) too_short_.add(run.line);
    if (run.line != block_.line) close_block();
    block_.line = run.line;
    const double lost = run.advance_s - run.nominal_s;
    block_.lost_s += lost;
    if (lost > block_worst_) {
      block_worst_ = lost;
      block_.limited_by = run.limit;
    }
  }

  ProgramTime finish(double estimated_s, const ReadSummary& summary, std::size_t moves,
                     const Occurrences& stops) {
    close_block();
    time_.estimated_s = estimated_s;
    time_.feed_s = std::max(estimated_s - time_.rapid_s - time_.dwell_s, 0.0);
    time_.blocks = summary.blocks;
    time_.moves = moves;
    std::sort(slowest_.begin(), slowest_.end(),
              [](const SlowBlock& a, const SlowBlock& b) { return a.lost_s > b.lost_s; });
    time_.slowest_blocks = std::move(slowest_);
    if (!summary.units_stated && moves > 0) {
      time_.warnings.push_back({WarningCode::units_assumed,
                                "the program states no units (G20/G21, G70/G71): read as mm"});
    }
    if (stops.count > 0) {
      time_.warnings.push_back(
          {WarningCode::untimed_stop,
           where(stops) + " stop for the operator or a tool change (M0, M1, M6): not timed"});
    }
    if (feed_capped_.count > 0) {
      time_.warnings.push_back(
          {WarningCode::axis_caps_feed,
           where(feed_capped_) + " ask for a feed above what the axes allow along them"});
    }
    if (too_short_.count > 0) {
      time_.warnings.push_back(
          {WarningCode::segment_too_short,
           where(too_short_) + " are too short for their feed at one segment per servo period"});
    }
    return std::move(time_);
  }

 private:
  // Keeps the kSlowestBlocks blocks that lost the most (a block's runs come one after another).
  void close_block() {
    if (block_.line == 0 || !(block_.lost_s > kNothingLostS)) {
      block_ = {};
      block_worst_ = -1.0;
      return;
    }
    if (slowest_.size() < kSlowestBlocks) {
      slowest_.push_back(block_);
    } else {
      auto least = std::min_element(
          slowest_.begin(), slowest_.end(),
          [](const SlowBlock& a, const SlowBlock& b) { return a.lost_s < b.lost_s; });
      if (block_.lost_s > least->lost_s) *least = block_;
    }
    block_ = {};
    block_worst_ = -1.0;
  }

  ProgramTime time_;
  SlowBlock block_;
  double block_worst_ = -1.0;
  std::vector<SlowBlock> slowest_;
  Occurrences feed_capped_;
  Occurrences too_short_;
};

// The path velocity at evenly spaced times (overlapping runs of a parabolic blend add up, as
// LinuxCNC reports them).
class ProfileSampler {
 public:
  ProfileSampler(int points, double total_s)
      : step_s_(total_s / (points - 1)), velocity_(static_cast<std::size_t>(points), 0.0) {}

  void add(const Run& run) {
    if (!run.motion || !(step_s_ > 0.0)) return;
    const double end = run.start_s + run.duration_s;
    const auto first = static_cast<std::size_t>(std::max(std::ceil(run.start_s / step_s_), 0.0));
    for (std::size_t k = first; k < velocity_.size(); ++k) {
      const double t = static_cast<double>(k) * step_s_;
      if (t > end) break;
      velocity_[k] += velocity_at(run, t - run.start_s);
    }
  }

  std::vector<ProfilePoint> points() const {
    std::vector<ProfilePoint> out;
    out.reserve(velocity_.size());
    for (std::size_t k = 0; k < velocity_.size(); ++k) {
      out.push_back({static_cast<double>(k) * step_s_, velocity_[k]});
    }
    return out;
  }

 private:
  static double velocity_at(const Run& run, double tau) {
    if (tau <= run.accel_s) {
      return run.accel_s > 0.0 ? run.v_start + (run.v_peak - run.v_start) * tau / run.accel_s
                               : run.v_peak;
    }
    tau -= run.accel_s;
    if (tau <= run.cruise_s) return run.v_peak;
    tau -= run.cruise_s;
    const double decel_s = run.duration_s - run.accel_s - run.cruise_s;
    if (!(decel_s > 0.0)) return run.v_end;
    return std::max(run.v_peak - (run.v_peak - run.v_end) * std::min(tau / decel_s, 1.0), 0.0);
  }

  double step_s_;
  std::vector<double> velocity_;
};

bool axis_moves(const Move& move, std::size_t axis) {
  if (move.kind == MoveKind::arc) {
    switch (move.arc.plane) {
      case Plane::xy:
        if (axis == 0 || axis == 1) return true;
        break;
      case Plane::xz:
        if (axis == 0 || axis == 2) return true;
        break;
      case Plane::yz:
        if (axis == 1 || axis == 2) return true;
        break;
    }
  }
  return move.start[axis] != move.end[axis];
}

bool is_motion(MoveKind kind) {
  return kind == MoveKind::rapid || kind == MoveKind::line || kind == MoveKind::arc;
}

}  // namespace

ProgramTimeOutcome time_program(const ProgramTimeParams& params) {
  Accounting accounting;
  std::optional<AxisNotDescribed> missing;
  std::size_t moves = 0;
  Occurrences stops;

  // One pass times and sums; a second one, when a profile is asked for, samples it (the sample
  // times need the total, and keeping every run instead would cost memory per block).
  const auto pass = [&](ProfileSampler* sampler, double& elapsed) {
    const bool first = sampler == nullptr;
    Planner planner(params.machine, [&](const Run& run) {
      if (first) accounting.add(run);
      if (sampler != nullptr) sampler->add(run);
    });
    auto read = read_program(params.program, params.read, [&](const Move& move) {
      if (missing) return;
      if (is_motion(move.kind)) {
        for (std::size_t axis = 0; axis < kAxisCount; ++axis) {
          if (!params.machine.axes[axis] && axis_moves(move, axis)) {
            missing = AxisNotDescribed{static_cast<Axis>(axis), move.line};
            return;
          }
        }
        if (first) ++moves;
      } else if (move.kind == MoveKind::untimed_stop && first) {
        stops.add(move.line);
      }
      planner.add(move);
    });
    planner.finish();
    elapsed = planner.elapsed_s();
    return read;
  };

  double estimated_s = 0.0;
  auto read = pass(nullptr, estimated_s);
  if (auto* error = std::get_if<ReadError>(&read)) return *error;
  if (missing) return *missing;
  ProgramTime time = accounting.finish(estimated_s, std::get<ReadSummary>(read), moves, stops);
  if (params.profile_points >= kMinProfilePoints) {
    ProfileSampler sampler(params.profile_points, estimated_s);
    double ignored = 0.0;
    pass(&sampler, ignored);
    time.profile = sampler.points();
  }
  return time;
}

std::string_view limit_name(Limit limit) {
  switch (limit) {
    case Limit::feed:
      return "feed";
    case Limit::axis_velocity:
      return "axis_velocity";
    case Limit::acceleration:
      return "acceleration";
    case Limit::arc:
      return "arc";
    case Limit::segment_length:
      return "segment_length";
    case Limit::blend:
      return "blend";
  }
  return "feed";
}

char axis_letter(Axis axis) {
  constexpr char kLetters[] = {'x', 'y', 'z', 'a', 'b', 'c'};
  return kLetters[index(axis)];
}

}  // namespace cutcalc::domain::machine_time
