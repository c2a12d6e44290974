#include "api/problem.h"

#include <nlohmann/json.hpp>

namespace cutcalc::api {
namespace {

struct ProblemType {
  int status;
  const char* type;
  const char* title;
};

ProblemType describe(ProblemKind kind) {
  switch (kind) {
    case ProblemKind::bad_request:
      return {400, "urn:cutcalc:problem:bad-request", "Bad request"};
    case ProblemKind::malformed_json:
      return {400, "urn:cutcalc:problem:malformed-json", "Malformed JSON"};
    case ProblemKind::payload_too_large:
      return {413, "urn:cutcalc:problem:payload-too-large", "Payload too large"};
    case ProblemKind::unsupported_media_type:
      return {415, "urn:cutcalc:problem:unsupported-media-type", "Unsupported media type"};
    case ProblemKind::invalid_input:
      return {422, "urn:cutcalc:problem:invalid-input", "Invalid input"};
    case ProblemKind::impossible_input:
      return {422, "urn:cutcalc:problem:impossible-input", "Input impossible for the model"};
    case ProblemKind::not_found:
      return {404, "urn:cutcalc:problem:not-found", "Not found"};
    case ProblemKind::method_not_allowed:
      return {405, "urn:cutcalc:problem:method-not-allowed", "Method not allowed"};
    case ProblemKind::unavailable:
      return {503, "urn:cutcalc:problem:unavailable", "Service unavailable"};
    case ProblemKind::internal_error:
      break;
  }
  return {500, "urn:cutcalc:problem:internal-error", "Internal error"};
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

}  // namespace

int http_status(ProblemKind kind) { return describe(kind).status; }

Problem invalid_input(std::vector<FieldError> errors) {
  Problem problem{ProblemKind::invalid_input, {}, std::move(errors)};
  if (problem.errors.empty()) {
    problem.detail = "the request is invalid";
  } else {
    const FieldError& first = problem.errors.front();
    // An error of the request as a whole ("give exactly one of ...") reads as it stands.
    problem.detail =
        first.pointer.empty() ? first.detail : field_name(first.pointer) + " " + first.detail;
    if (problem.errors.size() > 1) {
      problem.detail += " (and " + std::to_string(problem.errors.size() - 1) + " more)";
    }
  }
  return problem;
}

std::string problem_json(const Problem& problem, const std::string& instance,
                         const std::string& request_id) {
  const ProblemType type = describe(problem.kind);
  nlohmann::json errors = nlohmann::json::array();
  for (const FieldError& error : problem.errors) {
    errors.push_back({{"pointer", error.pointer}, {"detail", error.detail}});
  }
  nlohmann::json body = {{"type", type.type},
                         {"title", type.title},
                         {"status", type.status},
                         {"detail", problem.detail.empty() ? type.title : problem.detail},
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
                             const std::string& request_id) {
  return ApiResponse{http_status(problem.kind),
                     kProblemMediaType,
                     problem_json(problem, instance, request_id),
                     {}};
}

}  // namespace cutcalc::api
