#pragma once
// The machine-time answer (spec machine-time.md section 6): POST /v1/program-time's body and the
// program endpoints' `machine_time` member; and a program that cannot be timed as its field
// error.

#include <nlohmann/json.hpp>

#include "api/problem.h"
#include "domain/machine_time/program_time.h"

namespace cutcalc::api::machine_time {

nlohmann::json to_json(const domain::machine_time::ProgramTime& time);

// The 422 of a refused program or an undescribed axis: at `program_pointer` (line, column, word)
// or at /machine/axes (axis, line).
Problem to_problem(const domain::machine_time::ReadError& error,
                   const std::string& program_pointer);
Problem to_problem(const domain::machine_time::AxisNotDescribed& missing);

}  // namespace cutcalc::api::machine_time
