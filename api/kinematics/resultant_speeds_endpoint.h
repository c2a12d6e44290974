#pragma once
// POST /v1/resultant-speeds (API.md; spec resultant-speeds.md).

#include "api/json_endpoint.h"

namespace cutcalc::api::kinematics {

HandlerOutcome handle_resultant_speeds(const nlohmann::json& body);

}  // namespace cutcalc::api::kinematics
