#pragma once
// The one catalogue of what the API says when it refuses a request: every machine-readable error
// code (errors[].code, an enum in openapi.yaml), every problem title and every sentence, in each
// language the API speaks. A message is a template whose {name} placeholders are filled from the
// error's parameters, which the response also carries as JSON (errors[].minimum, ...).

#include <span>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace cutcalc::api {

enum class Language { en, ru };

// The Content-Language tag of a language: "en", "ru".
std::string_view language_tag(Language language);

enum class ErrorCode {
  // A field's own rules (api/field_reader.h).
  required,              // absent
  required_choice,       // absent; {allowed}
  not_a_number,          // not a JSON number
  not_finite,            // NaN, infinity or beyond a double
  not_an_integer,        // 2.5 where a whole number is needed
  must_be_positive,      // <= 0; {exclusive_minimum, maximum}
  must_not_be_negative,  // < 0; {minimum, maximum}
  below_resolution,      // in (0, minimum); {minimum}
  out_of_range,          // {minimum | exclusive_minimum, maximum | exclusive_maximum}
  wrong_list_length,     // not a list of min_items..max_items; {min_items, max_items}
  not_a_boolean,         // not true/false
  not_a_string,          // not a JSON string
  not_an_object,         // not a JSON object
  not_one_of,            // a string outside the choices; {allowed}
  unknown_field,         // a key the endpoint does not know
  body_not_an_object,    // the request body is JSON but not an object
  // Rules between fields that the API layer checks.
  exactly_one_field,             // {fields}
  exclusive_fields,              // {fields}: at most one
  requires_field,                // only with another field; {field}
  not_above,                     // must not exceed another field; {field}
  dialect_only,                  // a program field of one control only; {dialect}
  pass_program_only,             // a program field of the pass program only
  work_offset_unavailable,       // G58/G59 on sinumerik; {dialect, allowed}
  invalid_program_name,          // not 1-24 of A-Z, 0-9, _ from a letter
  reserved_program_name,         // a device name; {name}
  program_name_two_letters,      // sinumerik
  program_name_reserved_prefix,  // sinumerik; {prefix}
  // Valid fields that the model cannot answer together (domain::ErrorCode, one to one).
  no_contact,
  stroke_shorter_than_entry,
  entry_arc_wider_than_diameter,
  exit_arc_wider_than_diameter,
  exit_width_mismatch,
  offset_with_several_passes,
  allowance_wider_than_part,
  allowance_not_full_width,
  width_of_cut_exceeds_diameter,
  entry_feed_exceeds_feed,
  too_many_lateral_passes,
  too_many_depth_passes,
  contact_angle_outside_arc,
  target_needs_minor_edge_angle,
  cutter_not_smaller_than_bore,
  bore_feed_too_large,
  tolerance_unreachable,
  program_too_large,
  pass_program_too_large,
  program_needs_straight_path,
  word_prints_as_zero,
  // A problem's detail when it has no field errors (never in errors[]).
  empty_body,
  duplicate_key,           // {key}
  too_deeply_nested,       // {levels}
  invalid_json,            // {reason}: the JSON library's own words
  unsupported_media_type,  // {content_type}
  no_such_resource,        // {path}
  method_not_allowed,      // {method, path, allow}
  body_too_large,
  malformed_http,  // {reason}: the framing's own words
  shutting_down,
  connection_limit,
  internal_error,
};

// Every code, in declaration order: openapi.yaml's enum must list exactly those that can appear in
// errors[] (in_errors_list).
std::span<const ErrorCode> all_error_codes();
// The stable name sent as errors[].code: "must_be_positive".
std::string_view code_name(ErrorCode code);
// False for the codes that only ever describe a whole problem (empty_body ... internal_error).
bool in_errors_list(ErrorCode code);

// The sentence for `code` in `language`, placeholders filled from `params` (a JSON object).
std::string render_message(ErrorCode code, const nlohmann::json& params, Language language);

// Pieces of sentences that are not a code's message.
enum class Phrase {
  field_error,      // "{field} {message}": a problem's detail from its first field error
  and_n_more,       // " (and {count} more)"
  invalid_request,  // a detail when there is nothing more specific
  title_bad_request,
  title_malformed_json,
  title_payload_too_large,
  title_unsupported_media_type,
  title_invalid_input,
  title_impossible_input,
  title_not_found,
  title_method_not_allowed,
  title_internal_error,
  title_unavailable,
};
std::string render_phrase(Phrase phrase, const nlohmann::json& params, Language language);

}  // namespace cutcalc::api
