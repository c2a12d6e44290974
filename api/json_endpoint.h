#pragma once
// The pipeline every JSON calculation endpoint shares: media type -> strict parse -> the
// endpoint's handler (read fields -> domain -> serialise) -> a response with no NaN or infinity.

#include <functional>
#include <memory>
#include <string_view>
#include <variant>

#include <nlohmann/json.hpp>

#include "api/api_response.h"
#include "api/json_writer.h"
#include "api/problem.h"
#include "domain/common/text_source.h"

namespace cutcalc::api {

struct ApiRequest {
  std::string_view path;
  std::string_view content_type;
  std::string_view body;
  std::string_view request_id;
  std::string_view accept;           // the Accept header; only answers with a text form look at it
  Language language = Language::en;  // of problem details, from Accept-Language
  // The storage `body` views, when the caller owns it and can let it go: freed once the body is
  // parsed (a program of 32 MiB to time is not held twice while it is timed).
  std::string* body_storage = nullptr;
};

// An answer that also has a plain-text form (a G-code program), chosen by the Accept header.
struct JsonWithText {
  nlohmann::json json;
  std::string text;       // sent as text/plain; charset=us-ascii
  std::string file_name;  // for Content-Disposition: attachment
  // A program written as it is sent (both set, or neither): the text form instead of `text`, and
  // the JSON form's "program" member, which then goes first, instead of json["program"].
  std::unique_ptr<domain::TextSource> text_source;
  std::unique_ptr<domain::TextSource> program_source;
  // Members of the JSON form that no program text needs and that cost time (the polygon's
  // overcut prediction): added once the program has been written, so the first byte does not
  // wait for them; the text form never computes them. Empty: none.
  std::function<void(nlohmann::json&)> members_after_program = nullptr;
};

// Writes a streamed program whole into `text` and json["program"] (a caller that needs it at once).
void write_whole(JsonWithText& answer);
// Writes a body written as it is sent whole into `body` (a caller that needs it at once).
void write_whole(ApiResponse& response);

// JsonText: an answer written straight to text (api/json_writer.h), for the hottest endpoints.
using HandlerOutcome = std::variant<nlohmann::json, Problem, JsonWithText, JsonText>;
using JsonHandler = HandlerOutcome (*)(const nlohmann::json& body);

ApiResponse run_json_endpoint(const ApiRequest& request, JsonHandler handler);

// True when every number in `value` is finite (nlohmann would print NaN as null).
bool all_numbers_finite(const nlohmann::json& value);

}  // namespace cutcalc::api
