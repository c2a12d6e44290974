#pragma once
// The `machine` object of the program requests and of POST /v1/program-time (spec
// machine-time.md section 2; programs.md section 5): its limits that give warnings, and, with
// `axes`, the machine a program is timed on. Errors at /machine/<field>.

#include <optional>

#include "api/field_reader.h"
#include "domain/machine_time/gcode_reader.h"
#include "domain/machine_time/machine.h"
#include "domain/program/program_options.h"

namespace cutcalc::api::program {

struct MachineRequest {
  domain::program::MachineLimits limits;
  domain::machine_time::MachineKind kind = domain::machine_time::MachineKind::mill;
  // With `axes`: the machine to time on (its servo period, trajectory maximum and spindle limit
  // included); without: nullopt.
  std::optional<domain::machine_time::Machine> timing;
};

// What a request does with its `machine`.
enum class MachineUse {
  limits_only,    // POST /v1/main-time: writes no program, so nothing to time (axes: 422)
  program_mill,   // a program endpoint: axes optional, kind mill by default
  program_lathe,  // a lathe program endpoint: axes optional, kind lathe by default
  timing,         // POST /v1/program-time: axes required
};

// The `machine` object of `root`.
MachineRequest read_machine(ObjectReader& root, MachineUse use);

}  // namespace cutcalc::api::program
