#pragma once
// RFC 9457 problem details: the one error body of the whole API (API.md, "Common rules"). Every
// sentence comes from the catalogue (api/error_catalogue.h) in the language the client asked for.

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "api/api_response.h"
#include "api/error_catalogue.h"

namespace cutcalc::api {

// A code and its parameters: what the response carries, and what its sentence is made of.
struct Message {
  ErrorCode code = ErrorCode::internal_error;
  nlohmann::json params = nlohmann::json::object();  // e.g. {"minimum": 3, "maximum": 12}
};

struct FieldError {
  std::string pointer;  // RFC 6901 JSON Pointer into the request; "" = the combination of inputs
  ErrorCode code = ErrorCode::required;
  nlohmann::json params = nlohmann::json::object();  // sent beside code, e.g. "maximum": 12
};

enum class ProblemKind {
  bad_request,             // 400: an HTTP request the server could not process
  malformed_json,          // 400: a body that is not acceptable JSON
  payload_too_large,       // 413
  unsupported_media_type,  // 415
  invalid_input,           // 422: field errors
  impossible_input,        // 422: valid fields that the model cannot answer together
  not_found,               // 404
  method_not_allowed,      // 405
  internal_error,          // 500
  unavailable,             // 503
};

struct Problem {
  ProblemKind kind = ProblemKind::internal_error;
  std::optional<Message> detail;  // absent: said by the first field error
  std::vector<FieldError> errors;
};

int http_status(ProblemKind kind);

// A 422 for field errors; its detail names the first field, e.g. "cutter_diameter_mm must be >
// 0".
Problem invalid_input(std::vector<FieldError> errors);

// The response body in `language`; instance is the request path, request_id the request's id (may
// be empty).
std::string problem_json(const Problem& problem, const std::string& instance,
                         const std::string& request_id, Language language = Language::en);

// Where a problem's language came from: the request's Accept-Language, so that caches must keep
// the answers apart by it (Vary), or fixed (a request whose head could not be read is answered in
// English).
enum class LanguageChoice { negotiated, fixed };

// problem_json wrapped as a response with the right status, media type, Content-Language and,
// when negotiated, Vary: Accept-Language.
ApiResponse problem_response(const Problem& problem, const std::string& instance = {},
                             const std::string& request_id = {}, Language language = Language::en,
                             LanguageChoice choice = LanguageChoice::negotiated);

inline constexpr const char* kProblemMediaType = "application/problem+json";

}  // namespace cutcalc::api
