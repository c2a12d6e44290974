#pragma once
// POST /v1/main-time (API.md; spec entry-and-main-time.md section 9).

#include "api/json_endpoint.h"
#include "domain/entry/main_time.h"
#include "domain/program/program_options.h"

namespace cutcalc::api::entry {

HandlerOutcome handle_main_time(const nlohmann::json& body);

// The answer of /v1/main-time: the result and the machine-limit warnings (always a list).
nlohmann::json main_time_json(const domain::entry::MainTimeResult& result,
                              const domain::program::MachineLimits& limits);

}  // namespace cutcalc::api::entry
