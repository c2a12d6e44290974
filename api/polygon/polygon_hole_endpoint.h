#pragma once
// POST /v1/polygon-hole/gcode (API.md; spec polygon-holes.md section 10).

#include "api/json_endpoint.h"
#include "api/program/program_reader.h"

namespace cutcalc::api::polygon {

// The program it writes (its route row names it).
extern const program::ProgramPolicy kPolygonProgram;

HandlerOutcome handle_polygon_hole(const nlohmann::json& body);

}  // namespace cutcalc::api::polygon
