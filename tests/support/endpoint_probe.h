#pragma once
// One calculation endpoint called through its handler, no server, as the API tests probe it
// (the same pipeline as HTTP: api::run_json_endpoint), and the request edits they make.

#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "api/json_endpoint.h"

namespace cutcalc::testing {

class EndpointProbe {
 public:
  EndpointProbe(const char* path, api::JsonHandler handler) : path_(path), handler_(handler) {}

  [[nodiscard]] api::ApiResponse answer(const nlohmann::json& request,
                                        const char* accept = "application/json") const;
  // The pointers of a 422 answer's errors[]; {"status <n>"} when the answer is not a 422.
  [[nodiscard]] std::set<std::string> pointers(const nlohmann::json& request) const;
  // The codes of a 422 answer's errors[] (empty for another answer).
  [[nodiscard]] std::set<std::string> codes(const nlohmann::json& request) const;
  // Expects the text/plain answer of `request` to be the JSON answer's program, downloaded as
  // `file_name` (the JSON answer's file_name and the Content-Disposition attachment).
  void expect_program_download(const nlohmann::json& request, const std::string& file_name) const;

 private:
  const char* path_;
  api::JsonHandler handler_;
};

// What EndpointProbe::pointers gives for a 422 answer naming `pointer` alone.
inline std::set<std::string> only(const std::string& pointer) { return {pointer}; }

// The body of `response` as JSON (discarded when it is not JSON).
nlohmann::json parsed(const api::ApiResponse& response);

// `request` with `key` set to `value`, without `key`, with `program` as its program object.
nlohmann::json with(nlohmann::json request, const std::string& key, const nlohmann::json& value);
nlohmann::json without(nlohmann::json request, const std::string& key);
nlohmann::json with_program(nlohmann::json request, const nlohmann::json& program);

}  // namespace cutcalc::testing
