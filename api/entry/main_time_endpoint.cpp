#include "api/entry/main_time_endpoint.h"

#include "api/domain_error_mapping.h"
#include "api/entry/entry_json.h"
#include "api/entry/main_time_request.h"
#include "api/program/program_reader.h"
#include "domain/entry/main_time.h"
#include "domain/program/pass_program.h"

namespace cutcalc::api::entry {

HandlerOutcome handle_main_time(const nlohmann::json& body) {
  std::vector<FieldError> errors;
  ObjectReader in = root_reader(body, errors);
  const auto params = read_main_time_params(in);
  const auto limits = program::read_machine_limits(in);
  in.reject_unknown_fields();
  if (errors.empty()) {
    errors = main_time_alternative_errors(in);
  }
  if (!errors.empty()) {
    return invalid_input(std::move(errors));
  }
  const auto result = domain::entry::compute_main_time(params);
  if (!result.ok()) {
    return to_problem(result.error());
  }
  nlohmann::json json = to_json(result.value());
  json["warnings"] = program::to_json(domain::program::limit_warnings(
      result.value().spindle_speed_rpm, domain::program::setup_feeds_mm_per_min(result.value()),
      limits));
  return json;
}

}  // namespace cutcalc::api::entry
