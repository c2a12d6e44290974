#pragma once
// POST /v1/entry-length (API.md; spec entry-and-main-time.md section 9).

#include "api/json_endpoint.h"

namespace cutcalc::api::entry {

HandlerOutcome handle_entry_length(const nlohmann::json& body);

}  // namespace cutcalc::api::entry
