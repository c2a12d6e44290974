#include "api/kinematics/resultant_speeds_endpoint.h"

#include <cstdint>

#include "api/domain_error_mapping.h"
#include "api/field_reader.h"
#include "api/json_fields.h"
#include "api/milling_sense_json.h"
#include "domain/kinematics/resultant_speeds.h"

namespace cutcalc::api::kinematics {
namespace {

namespace model = domain::kinematics;

// no_contact is about the combination of the radii and the placement.
constexpr ErrorPointer kErrorPointers[] = {
    {domain::ErrorCode::contact_angle_outside_arc, "/contact_angles_deg"},  // + the element's index
};

constexpr std::size_t kMaxContactAngles = 1000;
// arc_samples: both ends of the arc at least; 361 = one sample per degree of a half-circle arc.
constexpr std::int64_t kMinArcSamples = 2;
constexpr std::int64_t kMaxArcSamples = 361;

// The request's fields; meaningful only when the reader recorded no error.
model::ResultantSpeedsParams read_params(ObjectReader& in) {
  model::ResultantSpeedsParams params;
  params.tool_radius_mm = in.required_number("tool_radius_mm", Bounds::positive()).value_or(0.0);
  params.workpiece_radius_mm =
      in.required_number("workpiece_radius_mm", Bounds::positive()).value_or(0.0);
  const auto center_distance = in.optional_number("center_distance_mm", Bounds::positive());
  const auto flat_depth = in.optional_number("flat_depth_mm", Bounds::positive());
  if (center_distance) {
    params.placement = model::CenterDistance{*center_distance};
  } else if (flat_depth) {
    params.placement = model::FlatDepth{*flat_depth};
  }
  params.tool_speed_rpm = in.required_number("tool_speed_rpm", Bounds::positive()).value_or(0.0);
  params.workpiece_speed_rpm =
      in.required_number("workpiece_speed_rpm", Bounds::non_negative()).value_or(0.0);
  params.milling = read_milling(in).value_or(domain::MillingSense::up);
  params.tool_feed_mm_per_min = in.number_or("tool_feed_mm_per_min", Bounds::magnitude(), 0.0);
  params.contact_angles_deg =
      in.optional_number_list("contact_angles_deg", Bounds{}, 1, kMaxContactAngles);
  if (in.has("arc_samples")) {
    params.arc_samples = static_cast<int>(
        in.required_integer("arc_samples", kMinArcSamples, kMaxArcSamples).value_or(0));
  }
  params.edge_inclination_deg =
      in.number_or("edge_inclination_deg", Bounds::open(-90.0, 90.0), 0.0);
  in.reject_unknown_fields();
  return params;
}

nlohmann::json to_json(const model::ContactPointSpeeds& point) {
  nlohmann::json out = nlohmann::json::object();
  CUTCALC_JSON_FIELDS(out, point, contact_angle_deg, contact_radius_mm, contact_polar_angle_deg,
                      tool_speed_m_per_min, workpiece_speed_m_per_min, resultant_feed_mm_per_min,
                      resultant_speed_m_per_min, resultant_angle_deg, kinematic_ratio,
                      normal_speed_m_per_min, along_edge_speed_m_per_min);
  out["sense"] = to_string(point.sense);
  return out;
}

}  // namespace

HandlerOutcome handle_resultant_speeds(const nlohmann::json& body) {
  std::vector<FieldError> errors;
  ObjectReader in = root_reader(body, errors);
  const auto params = read_params(in);
  if (errors.empty() && in.has("center_distance_mm") == in.has("flat_depth_mm")) {
    errors.push_back(
        {"", ErrorCode::exactly_one_field, {{"fields", {"center_distance_mm", "flat_depth_mm"}}}});
  }
  if (errors.empty() && in.has("contact_angles_deg") && in.has("arc_samples")) {
    errors.push_back(
        {"", ErrorCode::exclusive_fields, {{"fields", {"contact_angles_deg", "arc_samples"}}}});
  }
  if (!errors.empty()) {
    return invalid_input(std::move(errors));
  }
  const auto result = model::compute_resultant_speeds(params);
  if (!result.ok()) {
    return to_problem(result.error(), kErrorPointers);
  }
  nlohmann::json points = nlohmann::json::array();
  for (const auto& point : result.value().points) {
    points.push_back(to_json(point));
  }
  return nlohmann::json{{"engagement_half_angle_deg", result.value().engagement_half_angle_deg},
                        {"points", std::move(points)}};
}

}  // namespace cutcalc::api::kinematics
