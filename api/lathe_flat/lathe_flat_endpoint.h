#pragma once
// POST /v1/lathe-flat (spec lathe-flat.md): a flat milled on a lathe by C-axis steps with X
// following: geometry, step table, flatness error, layers, time and the program.

#include "api/json_endpoint.h"
#include "api/program/program_reader.h"

namespace cutcalc::api::lathe_flat {

// The program it writes (its route row names it).
extern const program::ProgramPolicy kLatheFlatProgram;

HandlerOutcome handle_lathe_flat(const nlohmann::json& body);

}  // namespace cutcalc::api::lathe_flat
