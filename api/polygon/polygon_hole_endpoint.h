#pragma once
// POST /v1/polygon-hole/gcode (API.md; spec polygon-holes.md section 10).

#include "api/json_endpoint.h"

namespace cutcalc::api::polygon {

HandlerOutcome handle_polygon_hole(const nlohmann::json& body);

}  // namespace cutcalc::api::polygon
