#pragma once
// POST /v1/program-time (API.md; spec machine-time.md): the time a control takes to run a
// program on a machine.

#include "api/json_endpoint.h"

namespace cutcalc::api::machine_time {

HandlerOutcome handle_program_time(const nlohmann::json& body);

}  // namespace cutcalc::api::machine_time
