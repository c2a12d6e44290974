#include "api/json_endpoint.h"

#include <cmath>
#include <string>

#include <spdlog/spdlog.h>

#include "api/accept_header.h"
#include "api/json_body.h"
#include "api/streamed_json.h"
#include "api/warning_catalogue.h"

namespace cutcalc::api {

bool all_numbers_finite(const nlohmann::json& value) {
  if (value.is_number_float()) {
    return std::isfinite(value.get<double>());
  }
  if (value.is_structured()) {
    for (const auto& element : value) {
      if (!all_numbers_finite(element)) {
        return false;
      }
    }
  }
  return true;
}

void write_whole(JsonWithText& answer) {
  if (answer.members_after_program) {
    answer.members_after_program(answer.json);
    answer.members_after_program = nullptr;
  }
  if (!answer.text_source) return;
  answer.text.clear();
  domain::write_all(*answer.text_source, answer.text);
  std::string program;
  domain::write_all(*answer.program_source, program);
  answer.json["program"] = std::move(program);
  answer.text_source.reset();
  answer.program_source.reset();
}

void write_whole(ApiResponse& response) {
  if (!response.body_source) return;
  domain::write_all(*response.body_source, response.body);
  response.body_source.reset();
}

namespace {

// A number that is not finite reached an answer: a bug, answered 500 and logged with the request.
ApiResponse non_finite(const ApiRequest& request, std::string_view body_start) {
  spdlog::error("non-finite number in the response of {} (request {}): {}", request.path,
                request.request_id, body_start);
  return problem_response(
      Problem{ProblemKind::internal_error, Message{ErrorCode::internal_error}, {}},
      std::string(request.path), std::string(request.request_id), request.language);
}

// An answer whose warnings[] speak the request's language: caches must keep the languages apart,
// as for problem details.
void say_language(ApiResponse& answer, Language language) {
  answer.headers.emplace_back("Content-Language", std::string(language_tag(language)));
  answer.headers.emplace_back("Vary", "Accept-Language");
}

}  // namespace

ApiResponse run_json_endpoint(const ApiRequest& request, JsonHandler handler) {
  const std::string instance(request.path);
  const std::string request_id(request.request_id);
  if (!is_json_media_type(request.content_type)) {
    const Message detail{ErrorCode::unsupported_media_type,
                         {{"content_type", std::string(request.content_type.substr(0, 100))}}};
    return problem_response(Problem{ProblemKind::unsupported_media_type, detail, {}}, instance,
                            request_id, request.language);
  }
  auto parsed = parse_json_body(request.body);
  if (auto* problem = std::get_if<Problem>(&parsed)) {
    return problem_response(*problem, instance, request_id, request.language);
  }
  // What a log line may quote of the body, kept before its storage goes.
  std::string_view body_start = request.body.substr(0, 4096);
  std::string kept_start;
  if (request.body_storage != nullptr) {
    kept_start = body_start;
    body_start = kept_start;
    std::string().swap(*request.body_storage);
  }
  HandlerOutcome outcome = handler(std::get<nlohmann::json>(parsed));
  if (auto* problem = std::get_if<Problem>(&outcome)) {
    return problem_response(*problem, instance, request_id, request.language);
  }
  // An answer with two forms is chosen by Accept: caches must keep the forms apart.
  bool chosen_by_accept = false;
  if (auto* document = std::get_if<JsonWithText>(&outcome)) {
    if (prefers_plain_text(request.accept)) {
      return ApiResponse{
          200,
          "text/plain; charset=us-ascii",
          std::move(document->text),
          {{"Content-Disposition", "attachment; filename=\"" + document->file_name + "\""},
           {"Vary", "Accept"}},
          std::move(document->text_source)};
    }
    if (document->program_source) {
      if (!all_numbers_finite(document->json)) return non_finite(request, body_start);
      const bool in_language = add_warning_messages(document->json, request.language);
      ApiResponse answer{200,
                         "application/json",
                         {},
                         {{"Vary", "Accept"}},
                         json_with_streamed_string("program", std::move(document->program_source),
                                                   std::move(document->json),
                                                   std::move(document->members_after_program))};
      if (in_language) say_language(answer, request.language);
      return answer;
    }
    write_whole(*document);
    nlohmann::json json_form = std::move(document->json);  // moved out before the variant changes
    outcome = std::move(json_form);
    chosen_by_accept = true;
  }
  auto* text = std::get_if<JsonText>(&outcome);
  auto* body = std::get_if<nlohmann::json>(&outcome);
  if (text != nullptr ? !text->all_finite : !all_numbers_finite(*body)) {
    return non_finite(request, body_start);
  }
  // A JsonText answer is written straight to text and carries no warnings.
  const bool in_language = body != nullptr && add_warning_messages(*body, request.language);
  ApiResponse answer{
      200, "application/json", text != nullptr ? std::move(text->text) : body->dump(), {}, {}};
  if (chosen_by_accept) answer.headers.emplace_back("Vary", "Accept");
  if (in_language) say_language(answer, request.language);
  return answer;
}

}  // namespace cutcalc::api
