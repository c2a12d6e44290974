#pragma once
// `machine_time` on the endpoints that write a program (spec machine-time.md sections 2 and 6):
// with machine.axes, the program's text as answered is timed by the same reader and planner as
// POST /v1/program-time, so the two agree on it; the text/plain program ends with a comment line
// stating the estimate.

#include <optional>

#include "api/json_endpoint.h"
#include "api/problem.h"
#include "api/program/machine_reader.h"
#include "domain/program/program_options.h"

namespace cutcalc::api::machine_time {

// Adds `machine_time` to the answer's JSON (timed from its "program" member) and the comment line
// to its text, when the request gave axes; a program the machine cannot run (an axis it lacks) is
// the 422 of /v1/program-time.
std::optional<Problem> add_machine_time(JsonWithText& answer,
                                        const program::MachineRequest& machine,
                                        domain::program::Dialect dialect);

}  // namespace cutcalc::api::machine_time
