#pragma once
// POST /v1/main-time/program (API.md; spec programs.md section 1): the passes of /v1/main-time as
// a machine program in one of three dialects, with its times.

#include "api/json_endpoint.h"

namespace cutcalc::api::entry {

HandlerOutcome handle_main_time_program(const nlohmann::json& body);

}  // namespace cutcalc::api::entry
