#include "api/entry/main_time_endpoint.h"

#include "api/domain_error_mapping.h"
#include "api/entry/entry_error_pointers.h"
#include "api/entry/entry_json.h"
#include "api/entry/main_time_request.h"
#include "api/program/program_reader.h"
#include "domain/program/pass_program.h"

namespace cutcalc::api::entry {

nlohmann::json main_time_json(const domain::entry::MainTimeResult& result,
                              const domain::program::MachineLimits& limits) {
  nlohmann::json json = to_json(result);
  json["warnings"] = program::to_json(
      domain::program::limit_warnings(domain::program::setup_top_spindle_rpm(result),
                                      domain::program::setup_feeds_mm_per_min(result), limits));
  return json;
}

HandlerOutcome handle_main_time(const nlohmann::json& body) {
  auto request = read_main_time_request(body, false);
  if (auto* problem = std::get_if<Problem>(&request)) return std::move(*problem);
  const auto& [params, machine, unused] = std::get<MainTimeRequest>(request);
  const auto result = domain::entry::compute_main_time(params);
  if (!result.ok()) {
    return to_problem(result.error(), kEntryErrorPointers);
  }
  return main_time_json(result.value(), machine.limits);
}

}  // namespace cutcalc::api::entry
