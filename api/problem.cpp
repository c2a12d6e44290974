#include "api/problem.h"

namespace cutcalc::api {
namespace {

struct ProblemType {
  int status;
  const char* type;
  Phrase title;
};

ProblemType describe(ProblemKind kind) {
  switch (kind) {
    case ProblemKind::bad_request:
      return {400, "urn:cutcalc:problem:bad-request", Phrase::title_bad_request};
    case ProblemKind::malformed_json:
      return {400, "urn:cutcalc:problem:malformed-json", Phrase::title_malformed_json};
    case ProblemKind::payload_too_large:
      return {413, "urn:cutcalc:problem:payload-too-large", Phrase::title_payload_too_large};
    case ProblemKind::unsupported_media_type:
      return {415, "urn:cutcalc:problem:unsupported-media-type",
              Phrase::title_unsupported_media_type};
    case ProblemKind::invalid_input:
      return {422, "urn:cutcalc:problem:invalid-input", Phrase::title_invalid_input};
    case ProblemKind::impossible_input:
      return {422, "urn:cutcalc:problem:impossible-input", Phrase::title_impossible_input};
    case ProblemKind::not_found:
      return {404, "urn:cutcalc:problem:not-found", Phrase::title_not_found};
    case ProblemKind::method_not_allowed:
      return {405, "urn:cutcalc:problem:method-not-allowed", Phrase::title_method_not_allowed};
    case ProblemKind::unavailable:
      return {503, "urn:cutcalc:problem:unavailable", Phrase::title_unavailable};
    case ProblemKind::internal_error:
      break;
  }
  return {500, "urn:cutcalc:problem:internal-error", Phrase::title_internal_error};
}

// "/entry/width_mm" -> "entry.width_mm".
std::string field_name(const std::string& pointer) {
  std::string name = pointer.substr(1);
  for (char& c : name) {
    if (c == '/') {
      c = '.';
    }
  }
  return name;
}

const nlohmann::json kNoParams = nlohmann::json::object();

// Without a detail of its own, a problem is told by its first field error: "entry.width_mm must be
// > 0 (and 2 more)"; an error of the request as a whole, or of the model, reads as it stands.
std::string detail_of(const Problem& problem, Language language) {
  if (problem.detail) {
    return render_message(problem.detail->code, problem.detail->params, language);
  }
  if (problem.errors.empty()) {
    return render_phrase(problem.kind == ProblemKind::invalid_input ? Phrase::invalid_request
                                                                    : describe(problem.kind).title,
                         kNoParams, language);
  }
  const FieldError& first = problem.errors.front();
  std::string detail = render_message(first.code, first.params, language);
  if (problem.kind == ProblemKind::invalid_input && !first.pointer.empty()) {
    detail = render_phrase(Phrase::field_error,
                           {{"field", field_name(first.pointer)}, {"message", detail}}, language);
  }
  if (problem.errors.size() > 1) {
    detail += render_phrase(Phrase::and_n_more, {{"count", problem.errors.size() - 1}}, language);
  }
  return detail;
}

}  // namespace

int http_status(ProblemKind kind) { return describe(kind).status; }

Problem invalid_input(std::vector<FieldError> errors) {
  return Problem{ProblemKind::invalid_input, std::nullopt, std::move(errors)};
}

std::string problem_json(const Problem& problem, const std::string& instance,
                         const std::string& request_id, Language language) {
  const ProblemType type = describe(problem.kind);
  nlohmann::json errors = nlohmann::json::array();
  for (const FieldError& error : problem.errors) {
    nlohmann::json entry = error.params.is_object() ? error.params : nlohmann::json::object();
    entry["pointer"] = error.pointer;
    entry["code"] = code_name(error.code);
    entry["detail"] = render_message(error.code, error.params, language);
    errors.push_back(std::move(entry));
  }
  nlohmann::json body = {{"type", type.type},
                         {"title", render_phrase(type.title, kNoParams, language)},
                         {"status", type.status},
                         {"detail", detail_of(problem, language)},
                         {"errors", std::move(errors)}};
  if (!instance.empty()) {
    body["instance"] = instance;
  }
  if (!request_id.empty()) {
    body["request_id"] = request_id;
  }
  // Details may quote user input: replace invalid UTF-8 instead of throwing.
  return body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

ApiResponse problem_response(const Problem& problem, const std::string& instance,
                             const std::string& request_id, Language language,
                             LanguageChoice choice) {
  ApiResponse response{http_status(problem.kind),
                       kProblemMediaType,
                       problem_json(problem, instance, request_id, language),
                       {{"Content-Language", std::string(language_tag(language))}},
                       {}};
  if (choice == LanguageChoice::negotiated) {
    response.headers.emplace_back("Vary", "Accept-Language");
  }
  return response;
}

}  // namespace cutcalc::api
