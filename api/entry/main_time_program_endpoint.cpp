#include "api/entry/main_time_program_endpoint.h"

#include "api/domain_error_mapping.h"
#include "api/entry/entry_error_pointers.h"
#include "api/entry/main_time_endpoint.h"
#include "api/entry/main_time_request.h"
#include "api/program/program_envelope.h"
#include "api/program/program_reader.h"
#include "domain/program/pass_program.h"

namespace cutcalc::api::entry {

HandlerOutcome handle_main_time_program(const nlohmann::json& body) {
  namespace model = domain::program;
  auto request = read_main_time_request(body, true);
  if (auto* problem = std::get_if<Problem>(&request)) return std::move(*problem);
  const auto& [params, machine, options] = std::get<MainTimeRequest>(request);
  const domain::program::MachineLimits& limits = machine.limits;
  const auto main_time = domain::entry::compute_main_time(params);
  if (!main_time.ok()) {
    return to_problem(main_time.error(), kEntryErrorPointers);
  }
  const auto written = model::write_pass_program(params, main_time.value(), options, limits);
  if (!written.ok()) {
    return to_problem(written.error(), kEntryErrorPointers);
  }
  const model::PassProgram& program = written.value();
  nlohmann::json json = {{"passes", program.passes},
                         {"main_time_min", main_time.value().main_time_min},
                         {"working_time_min", program.working_time_min},
                         {"plunge_time_min", program.plunge_time_min},
                         {"rapid_time_min", program.rapid_time_min},
                         {"cycle_time_min", program.cycle_time_min},
                         {"not_modelled", program.not_modelled},
                         {"warnings", program::to_json(program.warnings)},
                         {"main_time", main_time_json(main_time.value(), limits)}};
  return program::program_answer(
      std::move(json),
      {program.file_name, model::open_program_text(program), model::open_program_text(program)},
      options, kPassProgram, machine);
}

}  // namespace cutcalc::api::entry
