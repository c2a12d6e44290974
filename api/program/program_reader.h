#pragma once
// The `program` object and the top-level `machine` limits of the program requests (spec
// programs.md section 2), and the warnings' JSON form. Errors at /program/<field> and
// /machine/<field>.

#include <vector>

#include <nlohmann/json.hpp>

#include "api/field_reader.h"
#include "domain/program/program_options.h"

namespace cutcalc::api::program {

enum class ProgramKind {
  pass_program,  // POST /v1/main-time/program: every member
  polygon,       // POST /v1/polygon-hole/gcode: no clearance, plunge feed or rapid rate
  lathe,         // lathe programs (grooving-cycle.md 2): tools 1..99 on a turret, no length
                 // offset word, no safe Z or clearance
  lathe_flat,    // the lathe flat (lathe-flat.md 2): dialect, units, decimals, name and program
                 // number only; no Fanuc form yet (section 6.4)
};

// The `program` object of `root` (absent: every default of `kind`).
domain::program::ProgramOptions read_program_options(ObjectReader& root, ProgramKind kind);

// [{code, detail}, ...] of either program, the code by its name. Each item's message, in the
// request's language, is added by the pipeline that knows it (api/warning_catalogue.h).
nlohmann::json to_json(const std::vector<domain::program::Warning>& warnings);

}  // namespace cutcalc::api::program
