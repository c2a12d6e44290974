#pragma once
// The answer of every endpoint that writes a program (programs.md section 4): the endpoint's own
// members, and around them the program's envelope: the JSON form's `program` (first, streamed),
// `file_name`, `dialect`, `units` (and `decimals` where the policy says), the same program as the
// text/plain form, and `machine_time` when the request gave the machine's axes.

#include <functional>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "api/json_endpoint.h"
#include "api/program/machine_reader.h"
#include "api/program/program_reader.h"
#include "domain/common/text_source.h"
#include "domain/program/program_options.h"

namespace cutcalc::api::program {

// A program as its writer opens it: the two forms differ only where a writer says so (the
// polygon's comment lines).
struct WrittenProgram {
  std::string file_name;
  std::unique_ptr<domain::TextSource> json_form;  // the JSON answer's `program`
  std::unique_ptr<domain::TextSource> text_form;  // the text/plain answer
};

// `members` with the envelope of `program`, written with `options` by a writer of `policy`;
// `after_program`: members added once the program is written (JsonWithText's
// members_after_program). A machine the program cannot run on is its 422.
HandlerOutcome program_answer(nlohmann::json members, WrittenProgram program,
                              const domain::program::ProgramOptions& options,
                              const ProgramPolicy& policy, const MachineRequest& machine,
                              std::function<void(nlohmann::json&)> after_program = nullptr);

}  // namespace cutcalc::api::program
