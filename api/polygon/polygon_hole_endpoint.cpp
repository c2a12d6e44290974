#include "api/polygon/polygon_hole_endpoint.h"

#include <utility>
#include <vector>

#include "api/domain_error_mapping.h"
#include "api/field_reader.h"
#include "api/program/program_envelope.h"
#include "api/program/program_reader.h"
#include "domain/polygon/hole_geometry.h"
#include "domain/polygon/polygon_hole.h"

namespace cutcalc::api::polygon {

// A mill program whose passes are the polygon's own: of the motion members only safe_z_mm, by
// default the polygon's.
const program::ProgramPolicy kPolygonProgram{
    .motion = program::MotionMembers::safe_z,
    .safe_z_mm = domain::polygon::PolygonHoleParams{}.safe_z_mm};
namespace {

namespace model = domain::polygon;

constexpr ErrorPointer kErrorPointers[] = {
    {domain::ErrorCode::tolerance_unreachable, "/tolerance_mm"},
    {domain::ErrorCode::program_too_large, "/step_down_mm"},
    {domain::ErrorCode::word_prints_as_zero, "/spindle_speed_rpm"},
};

// Spec section 10: d below 1 mm is beyond the program's 0.1 um resolution; a tolerance below
// 0.1 um likewise; above 0.1 mm the fit is no longer a finishing path.
const Bounds kDiameter{1.0, true, kMaxLengthMm, true, {}};
const Bounds kTolerance{0.0001, true, 0.1, true, {}};
constexpr std::int64_t kMaxLoopsPerLayer = 100;

// The request: the program's parameters and whether the JSON answer carries the drawing.
struct PolygonHoleRequest {
  model::PolygonHoleParams params;
  bool include_geometry = false;
  program::MachineRequest machine;
};

model::PolygonHoleParams read_params(ObjectReader& in) {
  model::PolygonHoleParams params;
  params.faces = static_cast<int>(in.required_integer("faces", 3, 12).value_or(4));
  params.inscribed_diameter_mm =
      in.required_number("inscribed_diameter_mm", kDiameter).value_or(1.0);
  params.depth_mm = in.required_number("depth_mm", Bounds::positive()).value_or(1.0);
  params.step_down_mm = in.required_number("step_down_mm", Bounds::positive()).value_or(1.0);
  params.spindle_speed_rpm =
      in.required_number("spindle_speed_rpm", Bounds::positive()).value_or(1.0);
  params.tolerance_mm = in.number_or("tolerance_mm", kTolerance, params.tolerance_mm);
  const auto mode = in.optional_choice("synchronization", {"feed_per_rev", "c_axis"});
  params.synchronization =
      mode == "c_axis" ? model::Synchronization::c_axis : model::Synchronization::feed_per_rev;
  if (in.has("loops_per_layer")) {
    params.loops_per_layer =
        static_cast<int>(in.required_integer("loops_per_layer", 1, kMaxLoopsPerLayer).value_or(1));
  }
  params.safe_z_mm = in.number_or("safe_z_mm", Bounds::positive(), params.safe_z_mm);
  params.block_time_ms = in.number_or("block_time_ms", Bounds::positive(), params.block_time_ms);
  params.rapid_mm_per_min =
      in.number_or("rapid_mm_per_min", Bounds::positive(), params.rapid_mm_per_min);
  return params;
}

PolygonHoleRequest read_request(const nlohmann::json& body, ObjectReader& in,
                                std::vector<FieldError>& errors) {
  PolygonHoleRequest request;
  request.params = read_params(in);
  request.include_geometry = in.boolean_or("include_geometry", false);
  if (in.has("program")) {
    request.params.program = program::read_program_options(in, kPolygonProgram);
    const auto& given = body.at("program");
    if (given.is_object() && given.contains("safe_z_mm")) {
      if (in.has("safe_z_mm")) {
        errors.push_back({"/program/safe_z_mm",
                          ErrorCode::exclusive_fields,
                          {{"fields", {"safe_z_mm", "program.safe_z_mm"}}}});
      }
      request.params.safe_z_mm = request.params.program->safe_z_mm;
    }
  }
  // machine-time.md section 7: a polygon program blends within the fit's tolerance by default.
  if (request.params.program && request.params.program->path_control) {
    auto& control = *request.params.program->path_control;
    if (control.mode == domain::program::PathMode::blend && !control.tolerance_mm) {
      control.tolerance_mm = request.params.tolerance_mm;
    }
  }
  request.machine = program::read_machine(in, program::machine_use(kPolygonProgram));
  request.params.machine = request.machine.limits;
  in.reject_unknown_fields();
  return request;
}

nlohmann::json to_json(const model::RotorDimensions& rotor) {
  nlohmann::json arcs = nlohmann::json::array();
  for (const auto& arc : rotor.flank_arcs) {
    arcs.push_back({{"radius_mm", arc.radius_mm},
                    {"centre", {{"x_mm", arc.centre_x_mm}, {"y_mm", arc.centre_y_mm}}},
                    {"start_angle_deg", arc.start_angle_deg},
                    {"end_angle_deg", arc.end_angle_deg}});
  }
  return {{"corners", rotor.corners},
          {"corner_circle_diameter_mm", rotor.corner_circle_diameter_mm},
          {"corner_angle_deg", rotor.corner_angle_deg},
          {"flank_arcs", std::move(arcs)},
          {"width_min_mm", rotor.width_min_mm},
          {"width_max_mm", rotor.width_max_mm},
          {"neck_diameter_max_mm", rotor.neck_diameter_max_mm}};
}

nlohmann::json to_json(const model::PolygonHoleResult& result) {
  return {{"blocks_per_loop", result.blocks_per_loop},
          {"loop_length_mm", result.loop_length_mm},
          {"feed_per_rev_mm", result.feed_per_rev_mm},
          {"eccentricity_mm", result.eccentricity_mm},
          {"max_path_deviation_mm", result.max_path_deviation_mm},
          {"uncut_corner_area_mm2", result.uncut_corner_area_mm2},
          {"corner_gap_mm", result.corner_gap_mm},
          {"max_feed_by_block_rate_mm_per_min", result.max_feed_by_block_rate_mm_per_min},
          {"rotor", to_json(result.rotor)},
          {"corner_radius_mm", result.corner_radius_mm},
          {"working_time_min", result.time.working_min},
          {"plunge_time_min", result.time.plunge_min},
          {"rapid_time_min", result.time.rapid_min},
          {"cycle_time_min", result.time.cycle_min},
          {"warnings", program::to_json(result.warnings)},
          {"file_name", result.file_name}};
}

nlohmann::json to_json(const model::PlanePoint& point) {
  return {{"x_mm", point.x_mm}, {"y_mm", point.y_mm}};
}

nlohmann::json to_json(const std::vector<model::PlanePoint>& points) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& point : points) {
    list.push_back(to_json(point));
  }
  return list;
}

nlohmann::json to_json(const model::HoleGeometry& geometry) {
  nlohmann::json poses = nlohmann::json::array();
  for (const auto& pose : geometry.rotor_positions) {
    poses.push_back({{"phase_deg", pose.phase_deg},
                     {"axis", to_json(pose.axis)},
                     {"outline", to_json(pose.outline)}});
  }
  return {{"polygon", to_json(geometry.polygon)},
          {"centre_path", to_json(geometry.centre_path)},
          {"predicted_hole", to_json(geometry.predicted_hole)},
          {"rotor_positions", std::move(poses)},
          {"corner",
           {{"vertex", to_json(geometry.corner_vertex)},
            {"view_radius_mm", geometry.corner_view_radius_mm}}}};
}

}  // namespace

HandlerOutcome handle_polygon_hole(const nlohmann::json& body) {
  std::vector<FieldError> errors;
  ObjectReader in = root_reader(body, errors);
  const auto request = read_request(body, in, errors);
  if (!errors.empty()) {
    return invalid_input(std::move(errors));
  }
  const auto result = model::generate_polygon_hole(request.params);
  if (!result.ok()) {
    return to_problem(result.error(), kErrorPointers);
  }
  nlohmann::json json = to_json(result.value());
  const domain::program::ProgramOptions options =
      request.params.program.value_or(domain::program::ProgramOptions{});
  if (result.value().printed_path_deviation_mm) {
    json["printed_path_deviation_mm"] = *result.value().printed_path_deviation_mm;
  }
  if (request.include_geometry) {
    // Only the JSON answer: the plain-text program is the same with or without it.
    const auto geometry =
        model::sample_hole_geometry({request.params.faces, request.params.inscribed_diameter_mm});
    if (!geometry.ok()) {
      return to_problem(geometry.error(), kErrorPointers);
    }
    json["geometry"] = to_json(geometry.value());
  }
  return program::program_answer(
      std::move(json),
      {result.value().file_name, model::open_program_text(result.value(), false),
       model::open_program_text(result.value(), true)},
      options, kPolygonProgram, request.machine, [hole = result.value()](nlohmann::json& members) {
        members["predicted_overcut_mm"] = model::predicted_overcut_mm(hole);
      });
}

}  // namespace cutcalc::api::polygon
