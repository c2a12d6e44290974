#include "api/program/program_envelope.h"

#include <utility>

#include "api/machine_time/program_machine_time.h"

namespace cutcalc::api::program {

HandlerOutcome program_answer(nlohmann::json members, WrittenProgram program,
                              const domain::program::ProgramOptions& options,
                              const ProgramPolicy& policy, const MachineRequest& machine,
                              std::function<void(nlohmann::json&)> after_program) {
  members["file_name"] = program.file_name;
  members["dialect"] = domain::program::dialect_name(options.dialect);
  members["units"] = domain::program::units_name(options.units);
  if (policy.answer_states_decimals) {
    members["decimals"] = domain::program::decimals_of(options);
  }
  JsonWithText answer{std::move(members),           {},
                      std::move(program.file_name), std::move(program.text_form),
                      std::move(program.json_form), std::move(after_program)};
  if (auto problem = machine_time::add_machine_time(answer, machine, options.dialect)) {
    return std::move(*problem);
  }
  return answer;
}

}  // namespace cutcalc::api::program
