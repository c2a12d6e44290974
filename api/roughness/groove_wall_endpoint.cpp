#include "api/roughness/groove_wall_endpoint.h"

#include <cstdint>
#include <optional>
#include <vector>

#include "api/domain_error_mapping.h"
#include "api/field_reader.h"
#include "api/roughness/crest_branch_json.h"
#include "api/roughness/sample_fields.h"
#include "domain/roughness/groove_wall.h"
#include "domain/roughness/groove_wall_bearing.h"
#include "domain/roughness/groove_wall_curve.h"

namespace cutcalc::api::roughness {
namespace {

namespace model = domain::roughness;

nlohmann::json to_json(const model::GrooveWallCurve& curve) {
  nlohmann::json points = nlohmann::json::array();
  for (const auto& point : curve.points) {
    points.push_back(
        {{"feed_mm", point.feed_mm}, {"rz_um", point.rz_um}, {"branch", to_string(point.branch)}});
  }
  return points;
}

nlohmann::json to_json(const std::vector<model::BearingPoint>& bearing_curve) {
  nlohmann::json points = nlohmann::json::array();
  for (const auto& point : bearing_curve) {
    points.push_back({{"depth_um", point.depth_um}, {"material_ratio", point.material_ratio}});
  }
  return points;
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
  const std::optional<int> curve_points = optional_sample_count(in, "curve_points");
  const std::optional<int> bearing_points = optional_sample_count(in, "bearing_points");
  in.reject_unknown_fields();
  if (!errors.empty()) {
    return invalid_input(std::move(errors));
  }
  const auto result = model::compute_groove_wall_roughness(params);
  if (!result.ok()) {
    return to_problem(result.error(), {});
  }
  // Member by member: a brace list would build each member through a temporary two-element
  // array, a cost paid on every answer of this hot endpoint.
  nlohmann::json out = nlohmann::json::object();
  out["rz_um"] = result.value().rz_um;
  out["ra_um"] = result.value().ra_um;
  out["branch"] = to_string(result.value().branch);
  if (result.value().max_feed_mm) {
    out["max_feed_mm"] = *result.value().max_feed_mm;
  }
  if (curve_points) {
    const auto curve = model::compute_groove_wall_curve({params, *curve_points});
    if (!curve.ok()) {
      return to_problem(curve.error(), {});
    }
    out["curve"] = to_json(curve.value());
  }
  if (bearing_points) {
    const auto bearing_curve = model::compute_groove_wall_bearing_curve(params, *bearing_points);
    if (!bearing_curve.ok()) {
      return to_problem(bearing_curve.error(), {});
    }
    out["bearing_curve"] = to_json(bearing_curve.value());
  }
  return out;
}

}  // namespace cutcalc::api::roughness
