#include "api/roughness/groove_wall_endpoint.h"

#include "api/domain_error_mapping.h"
#include "api/field_reader.h"
#include "domain/roughness/groove_wall.h"

namespace cutcalc::api::roughness {
namespace {

namespace model = domain::roughness;

// Rz targets up to 1 km in micrometres: no meaningful surface is rougher.
constexpr double kMaxTargetUm = 1.0e9;

const char* to_string(model::CrestBranch branch) {
  switch (branch) {
    case model::CrestBranch::nose_arc:
      return "nose_arc";
    case model::CrestBranch::nose_arc_and_minor_edge:
      return "nose_arc_and_minor_edge";
    case model::CrestBranch::minor_edge_and_main_edge:
      break;
  }
  return "minor_edge_and_main_edge";
}

}  // namespace

HandlerOutcome handle_groove_wall(const nlohmann::json& body) {
  std::vector<FieldError> errors;
  ObjectReader in = root_reader(body, errors);
  model::GrooveWallParams params;
  params.feed_mm = in.required_number("feed_mm", Bounds::positive()).value_or(0.0);
  params.nose_radius_mm = in.required_number("nose_radius_mm", Bounds::positive()).value_or(0.0);
  params.minor_edge_angle_deg =
      in.required_number("minor_edge_angle_deg", Bounds{0.0, true, 90.0, false, {}}).value_or(0.0);
  params.target_rz_um = in.optional_number("target_rz_um", Bounds::positive(kMaxTargetUm));
  in.reject_unknown_fields();
  if (!errors.empty()) {
    return invalid_input(std::move(errors));
  }
  const auto result = model::compute_groove_wall_roughness(params);
  if (!result.ok()) {
    return to_problem(result.error());
  }
  nlohmann::json out = {{"rz_um", result.value().rz_um},
                        {"branch", to_string(result.value().branch)}};
  if (result.value().max_feed_mm) {
    out["max_feed_mm"] = *result.value().max_feed_mm;
  }
  return out;
}

}  // namespace cutcalc::api::roughness
