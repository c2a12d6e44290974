#pragma once
// The `program` object and the top-level `machine` limits of the program requests (spec
// programs.md section 2), and the warnings' JSON form. Errors at /program/<field> and
// /machine/<field>.

#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "api/field_reader.h"
#include "api/program/machine_reader.h"
#include "domain/machine_time/machine.h"
#include "domain/program/program_options.h"

namespace cutcalc::api::program {

// The members a program's `program` object may hold besides dialect, units, decimals, name,
// program_number and path_control, which every program reads.
enum class MotionMembers {
  none,    // the request's own members place the tool (the lathe programs)
  safe_z,  // safe_z_mm only; the pass program's others are refused by name (the polygon)
  passes,  // safe_z_mm, clearance_mm, plunge_feed_mm_per_min, rapid_mm_per_min (pass program)
};

// What differs between the programs the endpoints write (programs.md section 2): each endpoint's
// reader states its policy, and read_program_options, read_machine and program_answer follow it.
struct ProgramPolicy {
  // A lathe (grooving-cycle.md 2): tools 1..99 on a turret and no length offset word; its
  // `machine` is a lathe unless it says otherwise.
  domain::machine_time::MachineKind machine = domain::machine_time::MachineKind::mill;
  bool tool_and_state = true;  // tool_number, tool_length_offset (mill), work_offset, coolant
  MotionMembers motion = MotionMembers::none;
  std::optional<double> safe_z_mm = std::nullopt;  // its default; absent: ProgramOptions'
  bool fanuc = true;                    // the Fanuc dialect is offered (lathe-flat.md 6.4: not yet)
  bool answer_states_decimals = false;  // the JSON answer has `decimals` beside `units`
};

// The `program` object of `root` (absent: every default of `policy`).
domain::program::ProgramOptions read_program_options(ObjectReader& root,
                                                     const ProgramPolicy& policy);

// How the `machine` of a request for a program of `policy` is read.
inline MachineUse machine_use(const ProgramPolicy& policy) {
  return policy.machine == domain::machine_time::MachineKind::lathe ? MachineUse::program_lathe
                                                                    : MachineUse::program_mill;
}

// [{code, detail}, ...] of either program, the code by its name. Each item's message, in the
// request's language, is added by the pipeline that knows it (api/warning_catalogue.h).
nlohmann::json to_json(const std::vector<domain::program::Warning>& warnings);

}  // namespace cutcalc::api::program
