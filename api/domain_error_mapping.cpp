#include "api/domain_error_mapping.h"

#include <spdlog/spdlog.h>

namespace cutcalc::api {
namespace {

// The request field a domain error is about; "" = the combination of inputs.
const char* pointer_of(domain::ErrorCode code) {
  using domain::ErrorCode;
  switch (code) {
    case ErrorCode::no_contact:
      return "";
    case ErrorCode::stroke_shorter_than_entry:
      return "/length_mm";
    case ErrorCode::entry_arc_wider_than_diameter:
      return "/entry/width_mm";
    case ErrorCode::exit_arc_wider_than_diameter:
    case ErrorCode::exit_width_mismatch:
      return "/exit/width_mm";
    case ErrorCode::offset_with_several_passes:
      return "/offset_mm";
    case ErrorCode::allowance_wider_than_part:
    case ErrorCode::allowance_not_full_width:
      return "/allowance/width_mm";
    case ErrorCode::width_of_cut_exceeds_diameter:
      return "/allowance/width_of_cut_mm";
    case ErrorCode::entry_feed_exceeds_feed:
      return "/entry_feed_per_tooth_mm";
    case ErrorCode::too_many_lateral_passes:
      return "/allowance/width_of_cut_mm";
    case ErrorCode::too_many_depth_passes:
      return "/allowance/depth_of_cut_mm";
    case ErrorCode::contact_angle_outside_arc:
      return "/contact_angles_deg";  // to_problem appends the element's index
    case ErrorCode::target_needs_minor_edge_angle:
      return "";
    case ErrorCode::cutter_not_smaller_than_bore:
      return "/cutter_radius_mm";
    case ErrorCode::bore_feed_too_large:
      return "";
    case ErrorCode::tolerance_unreachable:
      return "/tolerance_mm";
    case ErrorCode::program_too_large:
      return "/step_down_mm";
    case ErrorCode::program_needs_straight_path:
      return "/extra_path_mm";
    case ErrorCode::word_prints_as_zero:
    case ErrorCode::pass_program_too_large:
      return "";
    case ErrorCode::not_converged:
      break;
  }
  return "";
}

}  // namespace

Problem to_problem(const domain::DomainError& error) {
  if (error.code == domain::ErrorCode::not_converged) {
    // Validated input that the numerics cannot answer is our bug: log the detail, answer
    // generically.
    spdlog::error("numerical procedure failed on validated input: {}", error.detail);
    return Problem{
        ProblemKind::internal_error, "the calculation failed; this is a bug in cutcalc", {}};
  }
  std::string pointer = pointer_of(error.code);
  if (error.index) {
    pointer += '/';
    pointer += std::to_string(*error.index);
  }
  return Problem{ProblemKind::impossible_input, error.detail, {FieldError{pointer, error.detail}}};
}

}  // namespace cutcalc::api
