#include "api/roughness/bore_milling_endpoint.h"

#include <cstdint>
#include <optional>

#include "api/domain_error_mapping.h"
#include "api/field_reader.h"
#include "api/json_fields.h"
#include "api/milling_sense_json.h"
#include "api/roughness/sample_fields.h"
#include "domain/roughness/bore_milling.h"
#include "domain/roughness/bore_milling_curve.h"
#include "domain/roughness/bore_milling_feed.h"

namespace cutcalc::api::roughness {
namespace {

namespace model = domain::roughness;

// bore_feed_too_large is about the combination of the feed, teeth, radii and sense,
// target_cusp_unreachable about the target together with the whole setup.
constexpr ErrorPointer kErrorPointers[] = {
    {domain::ErrorCode::cutter_not_smaller_than_bore, "/cutter_radius_mm"},
};

nlohmann::json to_json(const model::BoreMillingCurve& curve) {
  nlohmann::json points = nlohmann::json::array();
  for (const auto& point : curve.points) {
    points.push_back(
        {{"feed_per_rev_mm", point.feed_per_rev_mm}, {"cusp_height_um", point.cusp_height_um}});
  }
  return points;
}

}  // namespace

HandlerOutcome handle_bore_milling(const nlohmann::json& body) {
  std::vector<FieldError> errors;
  ObjectReader in = root_reader(body, errors);
  model::BoreMillingParams params;
  params.bore_radius_mm = in.required_number("bore_radius_mm", Bounds::positive()).value_or(0.0);
  params.cutter_radius_mm =
      in.required_number("cutter_radius_mm", Bounds::positive()).value_or(0.0);
  params.teeth = static_cast<int>(in.required_integer("teeth", 1, kMaxTeeth).value_or(1));
  params.feed_per_rev_mm = in.required_number("feed_per_rev_mm", Bounds::positive()).value_or(0.0);
  params.milling = read_milling(in).value_or(domain::MillingSense::up);
  const std::optional<double> target_cusp_um =
      in.optional_number("target_cusp_um", Bounds::positive(kMaxTargetUm));
  const std::optional<int> curve_points = optional_sample_count(in, "curve_points");
  in.reject_unknown_fields();
  if (!errors.empty()) {
    return invalid_input(std::move(errors));
  }
  const auto result = model::compute_bore_milling_cusp(params);
  if (!result.ok()) {
    return to_problem(result.error(), kErrorPointers);
  }
  const auto& cusp = result.value();
  nlohmann::json out = nlohmann::json::object();
  CUTCALC_JSON_FIELDS(out, cusp, cusp_height_um, approximate_cusp_height_um, feed_per_tooth_mm,
                      feed_per_tooth_on_bore_mm, pitch_angle_deg);
  std::optional<double> max_feed_per_rev_mm;
  if (target_cusp_um) {
    const auto max_feed = model::bore_milling_max_feed_mm(params, *target_cusp_um);
    if (!max_feed.ok()) {
      return to_problem(max_feed.error(), kErrorPointers);
    }
    max_feed_per_rev_mm = max_feed.value();
    out["max_feed_per_rev_mm"] = *max_feed_per_rev_mm;
  }
  if (curve_points) {
    const auto curve =
        model::compute_bore_milling_curve({params, max_feed_per_rev_mm, *curve_points});
    if (!curve.ok()) {
      return to_problem(curve.error(), kErrorPointers);
    }
    out["curve"] = to_json(curve.value());
  }
  return out;
}

}  // namespace cutcalc::api::roughness
