#include "api/domain_error_mapping.h"

#include <spdlog/spdlog.h>

#include "domain/entry/main_time.h"
#include "domain/polygon/polygon_hole.h"
#include "domain/program/pass_program.h"

namespace cutcalc::api {
namespace {

struct Mapping {
  const char* pointer;  // the request field the error is about; "" = the combination of inputs
  ErrorCode code;
  nlohmann::json params = nlohmann::json::object();
};

Mapping mapping_of(domain::ErrorCode code) {
  using domain::ErrorCode;
  using Api = api::ErrorCode;
  const auto limit = [](double maximum) { return nlohmann::json{{"maximum", maximum}}; };
  switch (code) {
    case ErrorCode::no_contact:
      return {"", Api::no_contact};
    case ErrorCode::stroke_shorter_than_entry:
      return {"/length_mm", Api::stroke_shorter_than_entry};
    case ErrorCode::entry_arc_wider_than_diameter:
      return {"/entry/width_mm", Api::entry_arc_wider_than_diameter};
    case ErrorCode::exit_arc_wider_than_diameter:
      return {"/exit/width_mm", Api::exit_arc_wider_than_diameter};
    case ErrorCode::exit_width_mismatch:
      return {"/exit/width_mm", Api::exit_width_mismatch};
    case ErrorCode::offset_with_several_passes:
      return {"/offset_mm", Api::offset_with_several_passes};
    case ErrorCode::allowance_wider_than_part:
      return {"/allowance/width_mm", Api::allowance_wider_than_part};
    case ErrorCode::allowance_not_full_width:
      return {"/allowance/width_mm", Api::allowance_not_full_width};
    case ErrorCode::width_of_cut_exceeds_diameter:
      return {"/allowance/width_of_cut_mm", Api::width_of_cut_exceeds_diameter};
    case ErrorCode::entry_feed_exceeds_feed:
      return {"/entry_feed_per_tooth_mm", Api::entry_feed_exceeds_feed};
    case ErrorCode::too_many_lateral_passes:
      return {"/allowance/width_of_cut_mm", Api::too_many_lateral_passes,
              limit(static_cast<double>(domain::entry::kMaxPassCount))};
    case ErrorCode::too_many_depth_passes:
      return {"/allowance/depth_of_cut_mm", Api::too_many_depth_passes,
              limit(static_cast<double>(domain::entry::kMaxPassCount))};
    case ErrorCode::contact_angle_outside_arc:
      return {"/contact_angles_deg", Api::contact_angle_outside_arc};  // + the element's index
    case ErrorCode::target_needs_minor_edge_angle:
      return {"", Api::target_needs_minor_edge_angle};
    case ErrorCode::cutter_not_smaller_than_bore:
      return {"/cutter_radius_mm", Api::cutter_not_smaller_than_bore};
    case ErrorCode::bore_feed_too_large:
      return {"", Api::bore_feed_too_large};
    case ErrorCode::tolerance_unreachable:
      return {"/tolerance_mm", Api::tolerance_unreachable,
              limit(domain::polygon::kMaxBiarcsPerEllipseArc)};
    case ErrorCode::program_too_large:
      return {"/step_down_mm", Api::program_too_large,
              limit(domain::polygon::kMaxProgramArcBlocks)};
    case ErrorCode::program_needs_straight_path:
      return {"/extra_path_mm", Api::program_needs_straight_path};
    case ErrorCode::word_prints_as_zero:
      return {"", Api::word_prints_as_zero};
    case ErrorCode::pass_program_too_large:
      return {"", Api::pass_program_too_large, limit(domain::program::kMaxProgramBlocks)};
    case ErrorCode::not_converged:
      break;
  }
  return {"", Api::internal_error};
}

}  // namespace

Problem to_problem(const domain::DomainError& error) {
  if (error.code == domain::ErrorCode::not_converged) {
    // Validated input that the numerics cannot answer is our bug: log the detail, answer
    // generically.
    spdlog::error("numerical procedure failed on validated input: {}", error.detail);
    return Problem{ProblemKind::internal_error, Message{ErrorCode::internal_error}, {}};
  }
  Mapping mapping = mapping_of(error.code);
  std::string pointer = mapping.pointer;
  if (error.index) {
    pointer += '/';
    pointer += std::to_string(*error.index);
  }
  return Problem{ProblemKind::impossible_input,
                 std::nullopt,
                 {FieldError{std::move(pointer), mapping.code, std::move(mapping.params)}}};
}

}  // namespace cutcalc::api
