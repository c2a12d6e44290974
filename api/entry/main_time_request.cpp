#include "api/entry/main_time_request.h"

#include <optional>
#include <vector>

#include "api/entry/contour_reader.h"
#include "api/field_reader.h"
#include "api/program/program_reader.h"

namespace cutcalc::api::entry {
namespace {

using domain::entry::MainTimeParams;

domain::entry::Allowance read_allowance(ObjectReader& in) {
  ObjectReader allowance = in.object("allowance", true);
  domain::entry::Allowance out;
  out.width_mm = allowance.required_number("width_mm", Bounds::positive()).value_or(0.0);
  out.width_of_cut_mm =
      allowance.required_number("width_of_cut_mm", Bounds::positive()).value_or(0.0);
  out.depth_mm = allowance.required_number("depth_mm", Bounds::positive()).value_or(0.0);
  out.depth_of_cut_mm =
      allowance.required_number("depth_of_cut_mm", Bounds::positive()).value_or(0.0);
  allowance.reject_unknown_fields();
  return out;
}

// E39-E40: the finishing level; a field error for each bad member, and both speeds at "".
std::optional<domain::entry::Finish> read_finish(ObjectReader& in,
                                                 std::vector<FieldError>& errors) {
  ObjectReader finish = in.object("finish", false);
  if (!finish.present()) return std::nullopt;
  domain::entry::Finish out;
  out.depth_of_cut_mm = finish.required_number("depth_of_cut_mm", Bounds::positive()).value_or(0.0);
  out.feed_per_tooth_mm =
      finish.required_number("feed_per_tooth_mm", Bounds::positive()).value_or(0.0);
  const auto rpm = finish.optional_number("spindle_speed_rpm", Bounds::positive());
  const auto cutting_speed = finish.optional_number("cutting_speed_m_per_min", Bounds::positive());
  if (rpm) {
    out.speed = domain::entry::SpindleSpeed{*rpm};
  } else if (cutting_speed) {
    out.speed = domain::entry::CuttingSpeed{*cutting_speed};
  }
  if (finish.has("spindle_speed_rpm") && finish.has("cutting_speed_m_per_min")) {
    errors.push_back(
        {"",
         ErrorCode::exclusive_fields,
         {{"fields", {"finish.spindle_speed_rpm", "finish.cutting_speed_m_per_min"}}}});
  }
  finish.reject_unknown_fields();
  return out;
}

MainTimeParams read_params(ObjectReader& in, bool with_program, std::vector<FieldError>& errors) {
  MainTimeParams params;
  params.cutter_diameter_mm =
      in.required_number("cutter_diameter_mm", Bounds::positive()).value_or(0);
  params.teeth = static_cast<int>(in.required_integer("teeth", 1, kMaxTeeth).value_or(1));

  const auto rpm = in.optional_number("spindle_speed_rpm", Bounds::positive());
  const auto cutting_speed = in.optional_number("cutting_speed_m_per_min", Bounds::positive());
  if (rpm) {
    params.speed = domain::entry::SpindleSpeed{*rpm};
  } else if (cutting_speed) {
    params.speed = domain::entry::CuttingSpeed{*cutting_speed};
  }
  params.feed_per_tooth_mm =
      in.required_number("feed_per_tooth_mm", Bounds::positive()).value_or(0);
  const auto factor = in.optional_number("entry_feed_factor", Bounds::positive(1.0));
  const auto entry_feed_per_tooth =
      in.optional_number("entry_feed_per_tooth_mm", Bounds::positive());
  if (entry_feed_per_tooth) {
    params.entry_feed = domain::entry::EntryFeedPerTooth{*entry_feed_per_tooth};
  } else {
    domain::entry::EntryFeedFactor entry_feed;
    entry_feed.factor = factor.value_or(entry_feed.factor);
    params.entry_feed = entry_feed;
  }

  params.length_mm = in.required_number("length_mm", Bounds::positive()).value_or(0.0);
  params.extra_path_mm =
      in.number_or("extra_path_mm", Bounds::non_negative(), params.extra_path_mm);
  // programs.md 1.2: each pass of a program is one straight line (L1 = 0), a field rule like any
  // other, so it is listed with every other field error.
  if (with_program && params.extra_path_mm > 0.0) {
    in.add_error("extra_path_mm", ErrorCode::program_needs_straight_path);
  }
  params.approach_mm = in.number_or("approach_mm", Bounds::non_negative(), params.approach_mm);
  params.overrun_mm = in.number_or("overrun_mm", Bounds::non_negative(), params.overrun_mm);
  ObjectReader entry = in.object("entry", true);
  params.entry = read_contour(entry, ContourSide::entry).value_or(domain::entry::Contour{});
  ObjectReader exit = in.object("exit", true);
  params.exit = read_contour(exit, ContourSide::exit).value_or(domain::entry::Contour{});
  params.offset_mm = in.optional_number("offset_mm", Bounds::magnitude());
  params.allowance = read_allowance(in);
  if (in.optional_choice("pass_split", {"last_smaller", "equal"}) == "equal") {
    params.pass_split = domain::entry::PassSplit::equal;  // E37
  }
  params.finish = read_finish(in, errors);
  return params;
}

std::vector<FieldError> alternative_errors(const ObjectReader& in) {
  std::vector<FieldError> errors;
  if (in.has("spindle_speed_rpm") == in.has("cutting_speed_m_per_min")) {
    errors.push_back({"",
                      ErrorCode::exactly_one_field,
                      {{"fields", {"spindle_speed_rpm", "cutting_speed_m_per_min"}}}});
  }
  if (in.has("entry_feed_factor") && in.has("entry_feed_per_tooth_mm")) {
    errors.push_back({"",
                      ErrorCode::exclusive_fields,
                      {{"fields", {"entry_feed_factor", "entry_feed_per_tooth_mm"}}}});
  }
  return errors;
}

}  // namespace

std::variant<MainTimeRequest, Problem> read_main_time_request(const nlohmann::json& body,
                                                              bool with_program) {
  std::vector<FieldError> errors;
  ObjectReader in = root_reader(body, errors);
  MainTimeRequest request;
  request.params = read_params(in, with_program, errors);
  if (with_program) {
    request.program = program::read_program_options(in, kPassProgram);
  }
  request.machine = program::read_machine(
      in, with_program ? program::machine_use(kPassProgram) : program::MachineUse::limits_only);
  in.reject_unknown_fields();
  // Listed beside the fields' own errors: errors[] lists every field error.
  for (FieldError& error : alternative_errors(in)) errors.push_back(std::move(error));
  if (!errors.empty()) return invalid_input(std::move(errors));
  return request;
}

}  // namespace cutcalc::api::entry
