#include "api/lathe_flat/lathe_flat_endpoint.h"

#include <array>
#include <utility>
#include <vector>

#include "api/domain_error_mapping.h"
#include "api/field_reader.h"
#include "api/json_fields.h"
#include "api/program/program_envelope.h"
#include "api/program/program_reader.h"
#include "domain/lathe_flat/flat_program.h"
#include "domain/lathe_flat/flatness.h"
#include "domain/lathe_flat/lathe_flat.h"

namespace cutcalc::api::lathe_flat {

// Its `program` holds dialect, units, decimals, name and number only (lathe-flat.md 2); no Fanuc
// form yet (section 6.4).
const program::ProgramPolicy kLatheFlatProgram{.machine = domain::machine_time::MachineKind::lathe,
                                               .tool_and_state = false,
                                               .fanuc = false,
                                               .answer_states_decimals = true};
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
    CUTCALC_JSON_FIELDS(item, row, i, c_deg, x_mm, dx_mm, chord_mm);
    table.push_back(std::move(item));
  }
  return table;
}

nlohmann::json to_json(const model::LatheFlatResult& r) {
  nlohmann::json out = nlohmann::json::object();
  CUTCALC_JSON_FIELDS(out, r, axis_distance_mm, flat_depth_mm, flat_width_mm, face_width_mm,
                      across_flats_mm, engagement_half_angle_deg, sharp_corners, steps, layers,
                      layer_depths_mm, x_travel_mm, flatness_error_mm, flatness_error_estimate_mm,
                      cut_blocks, shortest_block_mm, max_feed_by_block_rate_mm_per_min,
                      cut_time_min, approach_time_min, machining_time_min, clear_x_mm);
  if (r.steps_for_tolerance) out["steps_for_tolerance"] = *r.steps_for_tolerance;
  out["steps_table"] = to_json(r.steps_table);
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
      program::read_program_options(in, kLatheFlatProgram);
  const program::MachineRequest machine =
      program::read_machine(in, program::machine_use(kLatheFlatProgram));
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
  const model::FlatProgram& program = written.value();
  return program::program_answer(
      to_json(flat.value()),
      {program.file_name, model::open_program_text(program), model::open_program_text(program)},
      options, kLatheFlatProgram, machine);
}

}  // namespace cutcalc::api::lathe_flat
