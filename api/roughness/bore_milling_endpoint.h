#pragma once
// POST /v1/roughness/bore-milling (API.md; spec roughness.md part B).

#include "api/json_endpoint.h"

namespace cutcalc::api::roughness {

HandlerOutcome handle_bore_milling(const nlohmann::json& body);

}  // namespace cutcalc::api::roughness
