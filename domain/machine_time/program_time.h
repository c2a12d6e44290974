#pragma once
// The time a control takes to run a program, and what it is made of (spec machine-time.md
// sections 1 and 6): the reader's moves (gcode_reader.h) through the planner (planner.h), summed
// as they leave it, so a program of many MB is timed in the memory of the look-ahead queue.

#include <cstddef>
#include <string_view>
#include <variant>
#include <vector>

#include "domain/machine_time/gcode_reader.h"
#include "domain/machine_time/machine.h"
#include "domain/machine_time/segment.h"
#include "domain/program/program_warning.h"

namespace cutcalc::domain::machine_time {

inline constexpr int kMinProfilePoints = 2;
inline constexpr int kMaxProfilePoints = 2000;
inline constexpr std::size_t kSlowestBlocks = 10;

struct ProgramTimeParams {
  std::string_view program;
  ReadOptions read;
  Machine machine;
  int profile_points = 0;  // 0: no profile; else kMinProfilePoints..kMaxProfilePoints
};

struct SlowBlock {
  std::size_t line = 0;
  double lost_s = 0.0;  // the block's time on the machine less its nominal time
  Limit limited_by = Limit::feed;
};

struct ProfilePoint {
  double t_s = 0.0;
  double velocity_per_s = 0.0;  // path velocity, mm/s (deg/s on a rotary-only move)
};

struct ProgramTime {
  double estimated_s = 0.0;  // T_e (M2)
  double nominal_s = 0.0;    // T_n (M1)
  double feed_s = 0.0;       // T_e's split: feed moves (and the control's own pauses)
  double rapid_s = 0.0;
  double dwell_s = 0.0;
  std::size_t blocks = 0;
  std::size_t moves = 0;
  double feed_length_mm = 0.0;
  double rapid_length_mm = 0.0;
  double rotary_deg = 0.0;                // rotary-only moves
  std::vector<SlowBlock> slowest_blocks;  // most time lost first
  std::vector<program::Warning> warnings;
  std::vector<ProfilePoint> profile;
};

// An axis the program moves that the machine does not describe.
struct AxisNotDescribed {
  Axis axis;
  std::size_t line = 0;
};

using ProgramTimeOutcome = std::variant<ProgramTime, ReadError, AxisNotDescribed>;

// Spec machine-time.md sections 1-6.
ProgramTimeOutcome time_program(const ProgramTimeParams& params);

std::string_view limit_name(Limit limit);
char axis_letter(Axis axis);

}  // namespace cutcalc::domain::machine_time
