#pragma once
// The request of POST /v1/main-time, which POST /v1/main-time/program takes too (with `program`).

#include <variant>

#include <nlohmann/json.hpp>

#include "api/problem.h"
#include "api/program/machine_reader.h"
#include "api/program/program_reader.h"
#include "domain/entry/main_time.h"
#include "domain/program/program_options.h"

namespace cutcalc::api::entry {

struct MainTimeRequest {
  domain::entry::MainTimeParams params;
  program::MachineRequest machine;          // `machine` (axes: the program endpoint only)
  domain::program::ProgramOptions program;  // `program` (defaults unless with_program)
};

// The pass program of POST /v1/main-time/program (programs.md section 2): a mill program with
// every member of `program`; its route row names it.
inline constexpr program::ProgramPolicy kPassProgram{.motion = program::MotionMembers::passes};

// Every field error (with `program`, and extra_path_mm 0, only when `with_program`), then the
// alternatives; a problem when anything is wrong.
std::variant<MainTimeRequest, Problem> read_main_time_request(const nlohmann::json& body,
                                                              bool with_program);

}  // namespace cutcalc::api::entry
