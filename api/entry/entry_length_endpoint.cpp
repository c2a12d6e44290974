#include "api/entry/entry_length_endpoint.h"

#include "api/domain_error_mapping.h"
#include "api/entry/contour_reader.h"
#include "api/entry/entry_error_pointers.h"
#include "api/entry/entry_json.h"
#include "api/field_reader.h"
#include "domain/entry/entry_length.h"
#include "domain/entry/entry_scheme.h"

namespace cutcalc::api::entry {
namespace {

struct EntryLengthRequest {
  domain::entry::EntryLengthParams params;
  bool include_scheme = false;  // answer the plan-view scheme too
};

// The request's fields; meaningful only when the reader recorded no error.
EntryLengthRequest read_request(ObjectReader& in) {
  EntryLengthRequest request;
  domain::entry::EntryLengthParams& params = request.params;
  params.cutter_diameter_mm =
      in.required_number("cutter_diameter_mm", Bounds::positive()).value_or(0);
  params.offset_mm = in.number_or("offset_mm", Bounds::magnitude(), params.offset_mm);
  params.approach_mm = in.number_or("approach_mm", Bounds::non_negative(), params.approach_mm);
  ObjectReader entry = in.object("entry", true);
  params.entry = read_contour(entry, ContourSide::entry).value_or(domain::entry::Contour{});

  ObjectReader exit = in.object("exit", false);
  const auto exit_contour = read_contour(exit, ContourSide::exit);
  if (exit.present()) {
    domain::entry::ExitSide side;
    side.contour = exit_contour.value_or(domain::entry::Contour{});
    side.length_mm = in.required_number("length_mm", Bounds::positive()).value_or(0.0);
    side.extra_path_mm = in.number_or("extra_path_mm", Bounds::non_negative(), side.extra_path_mm);
    side.overrun_mm = in.number_or("overrun_mm", Bounds::non_negative(), side.overrun_mm);
    params.exit = side;
  } else {
    // Path lengths only mean something with an exit: a lone one is a mistake, not a default.
    for (const char* key : {"length_mm", "extra_path_mm", "overrun_mm"}) {
      if (in.has(key)) {
        in.reject(key, ErrorCode::requires_field, {{"field", "exit"}});
      }
    }
  }
  request.include_scheme = in.boolean_or("include_scheme", false);
  in.reject_unknown_fields();
  return request;
}

}  // namespace

HandlerOutcome handle_entry_length(const nlohmann::json& body) {
  std::vector<FieldError> errors;
  ObjectReader in = root_reader(body, errors);
  const EntryLengthRequest request = read_request(in);
  if (!errors.empty()) {
    return invalid_input(std::move(errors));
  }
  const auto result = domain::entry::compute_entry_length(request.params);
  if (!result.ok()) {
    return to_problem(result.error(), kEntryErrorPointers);
  }
  if (!request.include_scheme) {
    return entry_length_answer(result.value(), nullptr);
  }
  const auto scheme = domain::entry::entry_scheme(request.params, result.value());
  if (!scheme.ok()) {
    return to_problem(scheme.error(), kEntryErrorPointers);
  }
  const nlohmann::json scheme_json = to_json(scheme.value());
  return entry_length_answer(result.value(), &scheme_json);
}

}  // namespace cutcalc::api::entry
