#include "support/endpoint_probe.h"

#include <gtest/gtest.h>

namespace cutcalc::testing {

using nlohmann::json;

api::ApiResponse EndpointProbe::answer(const json& request, const char* accept) const {
  const std::string body = request.dump();
  api::ApiResponse response =
      api::run_json_endpoint({path_, "application/json", body, "test", accept}, handler_);
  api::write_whole(response);
  return response;
}

std::set<std::string> EndpointProbe::pointers(const json& request) const {
  const api::ApiResponse response = answer(request);
  if (response.status != 422) return {"status " + std::to_string(response.status)};
  std::set<std::string> out;
  const json problem = parsed(response);  // alive for the loop (a temporary's member would not be)
  for (const auto& error : problem.at("errors")) {
    out.insert(error.at("pointer").get<std::string>());
  }
  return out;
}

std::set<std::string> EndpointProbe::codes(const json& request) const {
  std::set<std::string> out;
  const json problem = parsed(answer(request));
  if (!problem.contains("errors")) return out;
  for (const auto& error : problem.at("errors")) out.insert(error.at("code").get<std::string>());
  return out;
}

void EndpointProbe::expect_program_download(const json& request,
                                            const std::string& file_name) const {
  const api::ApiResponse text = answer(request, "text/plain");
  ASSERT_EQ(text.status, 200) << text.body;
  EXPECT_EQ(text.content_type, "text/plain; charset=us-ascii");
  const json body = parsed(answer(request));
  EXPECT_EQ(text.body, body.at("program").get<std::string>());
  EXPECT_EQ(body.at("file_name"), file_name);
  bool named = false;
  for (const auto& [name, value] : text.headers) {
    if (name == "Content-Disposition") {
      EXPECT_EQ(value, "attachment; filename=\"" + file_name + "\"");
      named = true;
    }
  }
  EXPECT_TRUE(named) << file_name;
}

json parsed(const api::ApiResponse& response) { return json::parse(response.body, nullptr, false); }

json with(json request, const std::string& key, const json& value) {
  request[key] = value;
  return request;
}

json without(json request, const std::string& key) {
  request.erase(key);
  return request;
}

json with_program(json request, const json& program) {
  request["program"] = program;
  return request;
}

}  // namespace cutcalc::testing
