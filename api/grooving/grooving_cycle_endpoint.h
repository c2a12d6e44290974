#pragma once
// POST /v1/grooving/cycle (API.md; spec grooving-cycle.md): the "v razvod" grooving cycle, its
// times, wall roughness and lathe program.

#include "api/json_endpoint.h"
#include "api/program/program_reader.h"

namespace cutcalc::api::grooving {

// The program it writes (its route row names it).
extern const program::ProgramPolicy kGroovingProgram;

HandlerOutcome handle_grooving_cycle(const nlohmann::json& body);

}  // namespace cutcalc::api::grooving
