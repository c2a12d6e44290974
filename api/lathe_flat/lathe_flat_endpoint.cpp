#include "api/lathe_flat/lathe_flat_endpoint.h"
#include "api/machine_time/program_machine_time.h"
#include "api/program/machine_reader.h"

#include <array>
#include <utility>
#include <vector>

#include "api/domain_error_mapping.h"
#include "api/field_reader.h"
#include "api/program/program_reader.h"
#include "domain/lathe_flat/flat_program.h"
#include "domain/lathe_flat/flatness.h"
#include "domain/lathe_flat/lathe_flat.h"

namespace cutcalc::api::lathe_flat {
namespace {

namespace model = domain::lathe_flat;

constexpr std::array kGeometryFields = {"flat_depth_mm", "flat_width_mm", "axis_distance_mm",
                                        "across_flats_mm"};
constexpr std::int64_t kMaxFlats = 12;
const Bounds kTolerance{1e-6, true, 1.0, true, {}};

// Section 7: exactly one of t, b, d, s (pointer ""); the one given names a flat_outside_part.
const char* read_geometry(ObjectReader& in, model::LatheFlatParams& params,
                          std::vector<FieldError>& errors) {
  params.flat_depth_mm = in.optional_number("flat_depth_mm", Bounds::positive());
  params.flat_width_mm = in.optional_number("flat_width_mm", Bounds::positive());
  params.axis_distance_mm = in.optional_number("axis_distance_mm", Bounds::positive());
  params.across_flats_mm = in.optional_number("across_flats_mm", Bounds::positive());
  const char* given = nullptr;
  int count = 0;
  for (const char* field : kGeometryFields) {
    if (in.has(field)) {
      given = field;
      ++count;
    }
  }
  if (count != 1) {
    errors.push_back(
        {"",
         ErrorCode::exactly_one_field,
         {{"fields", {"flat_depth_mm", "flat_width_mm", "axis_distance_mm", "across_flats_mm"}}}});
  }
  return given;
}

model::LatheFlatParams read_params(ObjectReader& in, std::vector<FieldError>& errors,
                                   const char*& geometry_field) {
  model::LatheFlatParams params;
  params.part_diameter_mm =
      in.required_number("part_diameter_mm", Bounds::positive()).value_or(1.0);
  geometry_field = read_geometry(in, params, errors);
  if (in.has("flats")) {
    params.flats = static_cast<int>(in.required_integer("flats", 1, kMaxFlats).value_or(1));
  }
  if (in.has("across_flats_mm") && params.flats == 1) {
    in.add_error("across_flats_mm", ErrorCode::needs_several_flats);
  }
  params.tool_radius_mm =
      in.number_or("tool_radius_mm", Bounds::non_negative(), params.tool_radius_mm);
  if (in.has("steps")) {
    params.steps = static_cast<int>(in.required_integer("steps", 1, model::kMaxSteps).value_or(1));
  }
  params.flatness_tolerance_mm = in.optional_number("flatness_tolerance_mm", kTolerance);
  if (!in.has("steps") && !in.has("flatness_tolerance_mm")) {
    errors.push_back(
        {"", ErrorCode::at_least_one_field, {{"fields", {"steps", "flatness_tolerance_mm"}}}});
  }
  params.layer_depth_mm = in.optional_number("layer_depth_mm", Bounds::positive());
  params.feed_mm_per_min = in.required_number("feed_mm_per_min", Bounds::positive()).value_or(1.0);
  params.block_time_ms = in.number_or("block_time_ms", Bounds::positive(), params.block_time_ms);
  params.clearance_mm = in.number_or("clearance_mm", Bounds::positive(), params.clearance_mm);
  params.z_mm = in.number_or("z_mm", Bounds::magnitude(), params.z_mm);
  return params;
}

nlohmann::json to_json(const std::vector<domain::lathe_flat::StepRow>& rows) {
  nlohmann::json table = nlohmann::json::array();
  for (const auto& row : rows) {
    nlohmann::json item = nlohmann::json::object();
    item["i"] = row.i;
    item["c_deg"] = row.c_deg;
    item["x_mm"] = row.x_mm;
    item["dx_mm"] = row.dx_mm;
    item["chord_mm"] = row.chord_mm;
    table.push_back(std::move(item));
  }
  return table;
}

nlohmann::json to_json(const model::LatheFlatResult& r) {
  nlohmann::json out = nlohmann::json::object();
  out["axis_distance_mm"] = r.axis_distance_mm;
  out["flat_depth_mm"] = r.flat_depth_mm;
  out["flat_width_mm"] = r.flat_width_mm;
  out["face_width_mm"] = r.face_width_mm;
  out["across_flats_mm"] = r.across_flats_mm;
  out["engagement_half_angle_deg"] = r.engagement_half_angle_deg;
  out["sharp_corners"] = r.sharp_corners;
  out["steps"] = r.steps;
  if (r.steps_for_tolerance) out["steps_for_tolerance"] = *r.steps_for_tolerance;
  out["layers"] = r.layers;
  out["layer_depths_mm"] = r.layer_depths_mm;
  out["x_travel_mm"] = r.x_travel_mm;
  out["steps_table"] = to_json(r.steps_table);
  out["flatness_error_mm"] = r.flatness_error_mm;
  out["flatness_error_estimate_mm"] = r.flatness_error_estimate_mm;
  out["cut_blocks"] = r.cut_blocks;
  out["shortest_block_mm"] = r.shortest_block_mm;
  out["max_feed_by_block_rate_mm_per_min"] = r.max_feed_by_block_rate_mm_per_min;
  out["cut_time_min"] = r.cut_time_min;
  out["approach_time_min"] = r.approach_time_min;
  out["machining_time_min"] = r.machining_time_min;
  out["clear_x_mm"] = r.clear_x_mm;
  out["warnings"] = program::to_json(r.warnings);
  return out;
}

}  // namespace

HandlerOutcome handle_lathe_flat(const nlohmann::json& body) {
  std::vector<FieldError> errors;
  ObjectReader in = root_reader(body, errors);
  const char* geometry_field = nullptr;
  const model::LatheFlatParams params = read_params(in, errors, geometry_field);
  const domain::program::ProgramOptions options =
      program::read_program_options(in, program::ProgramKind::lathe_flat);
  const program::MachineRequest machine =
      program::read_machine(in, program::MachineUse::program_lathe);
  in.reject_unknown_fields();
  if (!errors.empty()) {
    return invalid_input(std::move(errors));
  }
  const std::string geometry_pointer = std::string("/") + geometry_field;
  const std::array pointers = {
      ErrorPointer{domain::ErrorCode::flat_outside_part, geometry_pointer},
      ErrorPointer{domain::ErrorCode::flat_too_small, geometry_pointer},
      ErrorPointer{domain::ErrorCode::tolerance_unmet, "/flatness_tolerance_mm"},
  };
  const auto flat = model::compute_lathe_flat(params);
  if (!flat.ok()) {
    return to_problem(flat.error(), pointers);
  }
  const auto written = model::write_flat_program(params, flat.value(), options);
  if (!written.ok()) {
    return to_problem(written.error(), pointers);
  }
  nlohmann::json json = to_json(flat.value());
  json["file_name"] = written.value().file_name;
  json["dialect"] = domain::program::dialect_name(options.dialect);
  json["units"] = domain::program::units_name(options.units);
  json["decimals"] = domain::program::decimals_of(options);
  JsonWithText answer{std::move(json),
                      {},
                      written.value().file_name,
                      model::open_program_text(written.value()),
                      model::open_program_text(written.value())};
  if (auto problem = machine_time::add_machine_time(answer, machine, options.dialect)) {
    return std::move(*problem);
  }
  return answer;
}

}  // namespace cutcalc::api::lathe_flat
