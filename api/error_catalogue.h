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

// Every code the API sends, from the one list (api/error_codes.def): the domain's codes first, each
// the same number as its domain::ErrorCode, then the API's own.
enum class ErrorCode {
#define CUTCALC_API_ERROR(name, listed) name,
#include "api/error_codes.def"
#undef CUTCALC_API_ERROR
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
