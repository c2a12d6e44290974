#include "api/entry/main_time_program_endpoint.h"

#include "api/domain_error_mapping.h"
#include "api/entry/entry_json.h"
#include "api/entry/main_time_request.h"
#include "api/program/program_reader.h"
#include "domain/program/pass_program.h"

namespace cutcalc::api::entry {

HandlerOutcome handle_main_time_program(const nlohmann::json& body) {
  namespace model = domain::program;
  std::vector<FieldError> errors;
  ObjectReader in = root_reader(body, errors);
  const auto params = read_main_time_params(in);
  const auto options = program::read_program_options(in, program::ProgramKind::pass_program);
  const auto limits = program::read_machine_limits(in);
  in.reject_unknown_fields();
  if (errors.empty()) {
    errors = main_time_alternative_errors(in);
  }
  if (!errors.empty()) {
    return invalid_input(std::move(errors));
  }
  const auto main_time = domain::entry::compute_main_time(params);
  if (!main_time.ok()) {
    return to_problem(main_time.error());
  }
  const auto written = model::write_pass_program(params, main_time.value(), options, limits);
  if (!written.ok()) {
    return to_problem(written.error());
  }
  const model::PassProgram& program = written.value();
  nlohmann::json main_time_json = to_json(main_time.value());
  main_time_json["warnings"] = program::to_json(
      model::limit_warnings(main_time.value().spindle_speed_rpm,
                            model::setup_feeds_mm_per_min(main_time.value()), limits));
  nlohmann::json json = {{"program", program.program},
                         {"file_name", program.file_name},
                         {"dialect", model::dialect_name(options.dialect)},
                         {"units", model::units_name(options.units)},
                         {"passes", program.passes},
                         {"main_time_min", main_time.value().main_time_min},
                         {"working_time_min", program.working_time_min},
                         {"plunge_time_min", program.plunge_time_min},
                         {"rapid_time_min", program.rapid_time_min},
                         {"cycle_time_min", program.cycle_time_min},
                         {"not_modelled", program.not_modelled},
                         {"warnings", program::to_json(program.warnings)},
                         {"main_time", std::move(main_time_json)}};
  return JsonWithText{std::move(json), program.program, program.file_name};
}

}  // namespace cutcalc::api::entry
