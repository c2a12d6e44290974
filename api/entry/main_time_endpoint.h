#pragma once
// POST /v1/main-time (API.md; spec entry-and-main-time.md section 9).

#include "api/json_endpoint.h"

namespace cutcalc::api::entry {

HandlerOutcome handle_main_time(const nlohmann::json& body);

}  // namespace cutcalc::api::entry
