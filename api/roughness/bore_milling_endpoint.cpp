#include "api/roughness/bore_milling_endpoint.h"

#include "api/domain_error_mapping.h"
#include "api/field_reader.h"
#include "api/milling_sense_json.h"
#include "domain/roughness/bore_milling.h"

namespace cutcalc::api::roughness {
namespace {

// bore_feed_too_large is about the combination of the feed, teeth, radii and sense.
constexpr ErrorPointer kErrorPointers[] = {
    {domain::ErrorCode::cutter_not_smaller_than_bore, "/cutter_radius_mm"},
};

}  // namespace

HandlerOutcome handle_bore_milling(const nlohmann::json& body) {
  std::vector<FieldError> errors;
  ObjectReader in = root_reader(body, errors);
  domain::roughness::BoreMillingParams params;
  params.bore_radius_mm = in.required_number("bore_radius_mm", Bounds::positive()).value_or(0.0);
  params.cutter_radius_mm =
      in.required_number("cutter_radius_mm", Bounds::positive()).value_or(0.0);
  params.teeth = static_cast<int>(in.required_integer("teeth", 1, kMaxTeeth).value_or(1));
  params.feed_per_rev_mm = in.required_number("feed_per_rev_mm", Bounds::positive()).value_or(0.0);
  params.milling = read_milling(in).value_or(domain::MillingSense::up);
  in.reject_unknown_fields();
  if (!errors.empty()) {
    return invalid_input(std::move(errors));
  }
  const auto result = domain::roughness::compute_bore_milling_cusp(params);
  if (!result.ok()) {
    return to_problem(result.error(), kErrorPointers);
  }
  const auto& cusp = result.value();
  // Member by member: a brace list would build each member through a temporary two-element
  // array, a cost paid on every answer of this hot endpoint.
  nlohmann::json out = nlohmann::json::object();
  out["cusp_height_um"] = cusp.cusp_height_um;
  out["approximate_cusp_height_um"] = cusp.approximate_cusp_height_um;
  out["feed_per_tooth_mm"] = cusp.feed_per_tooth_mm;
  out["feed_per_tooth_on_bore_mm"] = cusp.feed_per_tooth_on_bore_mm;
  out["pitch_angle_deg"] = cusp.pitch_angle_deg;
  return out;
}

}  // namespace cutcalc::api::roughness
