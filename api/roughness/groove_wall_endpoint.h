#pragma once
// POST /v1/roughness/groove-wall (API.md; spec roughness.md part R).

#include "api/json_endpoint.h"

namespace cutcalc::api::roughness {

HandlerOutcome handle_groove_wall(const nlohmann::json& body);

}  // namespace cutcalc::api::roughness
