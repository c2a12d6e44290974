#include "api/grooving/grooving_cycle_endpoint.h"

#include <utility>
#include <vector>

#include "api/domain_error_mapping.h"
#include "api/field_reader.h"
#include "api/json_fields.h"
#include "api/program/program_envelope.h"
#include "api/program/program_reader.h"
#include "api/roughness/crest_branch_json.h"
#include "domain/grooving/grooving_cycle.h"
#include "domain/grooving/grooving_program.h"

namespace cutcalc::api::grooving {

// A lathe program whose cycle places the tool itself (grooving-cycle.md 2 and 5).
const program::ProgramPolicy kGroovingProgram{.machine = domain::machine_time::MachineKind::lathe,
                                              .answer_states_decimals = true};

namespace {

namespace model = domain::grooving;

constexpr ErrorPointer kErrorPointers[] = {
    {domain::ErrorCode::bottom_not_below_start, "/bottom_diameter_mm"},
    {domain::ErrorCode::groove_too_deep, "/groove_depth_mm"},
    {domain::ErrorCode::shift_too_wide, "/shift_mm"},
    {domain::ErrorCode::tool_too_wide, "/tool_width_mm"},
};

const Bounds kMinorEdgeAngle{0.0, true, 90.0, false, {}};
const Bounds kDwellRevolutions = Bounds::non_negative(1000.0);

// Exactly one of two members: both point at `second`, neither at `first` (spec section 6).
void exactly_one(ObjectReader& in, const char* first, const char* second) {
  if (in.has(first) && in.has(second)) {
    in.add_error(second, ErrorCode::exclusive_fields, {{"fields", {first, second}}});
  } else if (!in.has(first) && !in.has(second)) {
    in.add_error(first, ErrorCode::exactly_one_field, {{"fields", {first, second}}});
  }
}

model::SpindleMode read_spindle(ObjectReader& in) {
  exactly_one(in, "spindle_speed_rpm", "cutting_speed_m_per_min");
  model::SpindleMode spindle;
  spindle.spindle_speed_rpm = in.optional_number("spindle_speed_rpm", Bounds::positive());
  spindle.cutting_speed_m_per_min =
      in.optional_number("cutting_speed_m_per_min", Bounds::positive());
  spindle.max_spindle_rpm = in.has("cutting_speed_m_per_min") && !in.has("spindle_speed_rpm")
                                ? in.required_number("max_spindle_rpm", Bounds::positive())
                                : in.optional_number("max_spindle_rpm", Bounds::positive());
  return spindle;
}

model::GroovingCycleParams read_params(ObjectReader& in) {
  model::GroovingCycleParams params;
  params.groove_width_mm = in.required_number("groove_width_mm", Bounds::positive()).value_or(1.0);
  params.start_diameter_mm =
      in.required_number("start_diameter_mm", Bounds::positive()).value_or(1.0);
  exactly_one(in, "groove_depth_mm", "bottom_diameter_mm");
  params.bottom_diameter_mm = in.optional_number("bottom_diameter_mm", Bounds::positive());
  params.groove_depth_mm = in.optional_number("groove_depth_mm", Bounds::positive());
  params.groove_left_z_mm =
      in.required_number("groove_left_z_mm", Bounds::magnitude()).value_or(0.0);
  params.shift_mm = in.optional_number("shift_mm", Bounds::positive());
  params.tool_width_mm = in.optional_number("tool_width_mm", Bounds::positive());
  params.feed_per_rev_mm = in.required_number("feed_per_rev_mm", Bounds::positive()).value_or(1.0);
  params.spindle = read_spindle(in);
  params.nose_radius_mm = in.required_number("nose_radius_mm", Bounds::positive()).value_or(1.0);
  params.minor_edge_angle_deg =
      in.required_number("minor_edge_angle_deg", kMinorEdgeAngle).value_or(0.0);
  params.dwell_revolutions =
      in.number_or("dwell_revolutions", kDwellRevolutions, params.dwell_revolutions);
  params.approach_clearance_mm =
      in.number_or("approach_clearance_mm", Bounds::positive(), params.approach_clearance_mm);
  params.rapid_mm_per_min =
      in.number_or("rapid_mm_per_min", Bounds::positive(), params.rapid_mm_per_min);
  return params;
}

nlohmann::json to_json(const model::GroovingCycleResult& r) {
  nlohmann::json out = nlohmann::json::object();
  CUTCALC_JSON_FIELDS(
      out, r, tool_width_mm, shift_mm, groove_depth_mm, bottom_diameter_mm, approach_diameter_mm,
      revolutions, radial_revolutions, shift_revolutions, shifts, infeed_per_revolution_mm,
      shift_feed_mm_per_rev, final_shift_revolutions, spindle_revolutions, approach_time_min,
      plunge_time_min, shift_time_min, dwell_time_min, final_shift_time_min, retract_time_min,
      cycle_time_min, spindle_speed_at_start_rpm, spindle_speed_at_bottom_rpm, chip_thickness_mm,
      side_chip_thickness_mm, wall_pitch_mm, wall_rz_um, plain_plunge_rz_um);
  out["end_side"] = model::side_name(r.end_side);
  out["wall_rz_branch"] = roughness::to_string(r.wall_rz_branch);
  return out;
}

}  // namespace

HandlerOutcome handle_grooving_cycle(const nlohmann::json& body) {
  std::vector<FieldError> errors;
  ObjectReader in = root_reader(body, errors);
  const model::GroovingCycleParams params = read_params(in);
  const domain::program::ProgramOptions options =
      program::read_program_options(in, kGroovingProgram);
  const program::MachineRequest machine =
      program::read_machine(in, program::machine_use(kGroovingProgram));
  in.reject_unknown_fields();
  if (!errors.empty()) {
    return invalid_input(std::move(errors));
  }
  const auto cycle = model::compute_grooving_cycle(params);
  if (!cycle.ok()) {
    return to_problem(cycle.error(), kErrorPointers);
  }
  const auto written = model::write_grooving_program(params, cycle.value(), options);
  if (!written.ok()) {
    return to_problem(written.error(), kErrorPointers);
  }
  const model::GroovingProgram& program = written.value();
  nlohmann::json json = to_json(cycle.value());
  json["warnings"] = program::to_json(program.warnings);
  return program::program_answer(
      std::move(json),
      {program.file_name, model::open_program_text(program), model::open_program_text(program)},
      options, kGroovingProgram, machine);
}

}  // namespace cutcalc::api::grooving
