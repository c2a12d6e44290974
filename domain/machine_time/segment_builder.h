#pragma once
// A programmed move as the planner's segment (spec machine-time.md M1, M4, M5): its length, the
// feed it asks for, the velocity and acceleration the axes allow along it (LinuxCNC's canon:
// getStraightVelocity, getStraightAcceleration, ARC_FEED in src/emc/task/emccanon.cc), and its
// nominal time.

#include <optional>

#include "domain/machine_time/machine.h"
#include "domain/machine_time/move.h"
#include "domain/machine_time/segment.h"

namespace cutcalc::domain::machine_time {

// The segment of a rapid, line or arc; nullopt for a move of (nearly) zero length, which the
// control skips.
std::optional<Segment> build_segment(const Move& move, const Machine& machine);

}  // namespace cutcalc::domain::machine_time
