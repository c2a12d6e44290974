// Problems in the client's language: with Accept-Language: ru every title, detail and
// errors[].detail of every refused reference request is Russian, Content-Language says so, and the
// codes and pointers a program switches on are the same as in English.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "api/routes.h"
#include "support/route_table_check.h"
#include "support/test_server.h"

#ifndef CUTCALC_REFERENCE_DIR
#error "CUTCALC_REFERENCE_DIR must be defined"
#endif

namespace cutcalc::testing {
namespace {

using nlohmann::json;

bool has_cyrillic(const std::string& text) {
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte == 0xD0 || byte == 0xD1) return true;
  }
  return false;
}

struct Answer {
  int status = 0;
  std::string content_language;
  std::vector<std::string> vary;
  json body;
};

Answer send(const std::string& method, const std::string& path, const std::string& body,
            const std::string& accept_language,
            const std::string& content_type = "application/json") {
  auto client = TestServer::shared().client();
  httplib::Headers headers;
  if (!accept_language.empty()) headers.emplace("Accept-Language", accept_language);
  httplib::Result result = method == "POST" ? client->Post(path, headers, body, content_type)
                                            : client->Get(path, headers);
  Answer answer;
  if (!result) return answer;
  answer.status = result->status;
  answer.content_language = result->get_header_value("Content-Language");
  for (std::size_t i = 0; i < result->get_header_value_count("Vary"); ++i) {
    answer.vary.push_back(result->get_header_value("Vary", i));
  }
  answer.body = json::parse(result->body, nullptr, false);
  return answer;
}

// [path, request] of every reference case that the service refuses (422).
std::vector<std::pair<std::string, json>> refused_reference_requests() {
  std::vector<std::pair<std::string, json>> refused;
  for (const std::string& file :
       test_support::replayed_reference_files(CUTCALC_REFERENCE_DIR, api::calculation_routes())) {
    const json document = load_reference(file);
    for (const json& item : document.at("cases")) {
      if (item.at("expect").at("status") == 422) {
        refused.emplace_back(document.at("endpoint").get<std::string>(), item.at("request"));
      }
    }
  }
  return refused;
}

void expect_russian(const Answer& answer, const std::string& where) {
  EXPECT_EQ(answer.content_language, "ru") << where;
  ASSERT_TRUE(answer.body.is_object()) << where;
  EXPECT_TRUE(has_cyrillic(answer.body.value("title", ""))) << where << ": " << answer.body;
  EXPECT_TRUE(has_cyrillic(answer.body.value("detail", ""))) << where << ": " << answer.body;
  for (const json& error : answer.body.value("errors", json::array())) {
    EXPECT_TRUE(has_cyrillic(error.value("detail", ""))) << where << ": " << error;
  }
}

void expect_english(const Answer& answer, const std::string& where) {
  EXPECT_EQ(answer.content_language, "en") << where;
  EXPECT_FALSE(has_cyrillic(answer.body.dump())) << where << ": " << answer.body;
}

TEST(ProblemLanguage, EveryRefusedReferenceRequestIsExplainedInRussianWithTheSameCodes) {
  const auto refused = refused_reference_requests();
  ASSERT_GT(refused.size(), 30U);
  for (const auto& [path, request] : refused) {
    const std::string where = path + " " + request.dump();
    const Answer russian = send("POST", path, request.dump(), "ru-RU,ru;q=0.9,en;q=0.8");
    const Answer english = send("POST", path, request.dump(), "");
    ASSERT_EQ(russian.status, 422) << where;
    ASSERT_EQ(english.status, 422) << where;
    expect_russian(russian, where);
    expect_english(english, where);
    EXPECT_EQ(russian.body.at("type"), english.body.at("type")) << where;
    const json& ru_errors = russian.body.at("errors");
    const json& en_errors = english.body.at("errors");
    ASSERT_EQ(ru_errors.size(), en_errors.size()) << where;
    ASSERT_FALSE(en_errors.empty()) << where;
    for (std::size_t i = 0; i < en_errors.size(); ++i) {
      EXPECT_FALSE(en_errors[i].value("code", "").empty()) << where;
      json ru_rest = ru_errors[i];
      json en_rest = en_errors[i];
      ru_rest.erase("detail");
      en_rest.erase("detail");
      EXPECT_EQ(ru_rest, en_rest) << where;  // pointer, code and parameters
    }
  }
}

TEST(ProblemLanguage, ProblemsOutsideTheCalculationsFollowTheLanguageToo) {
  expect_russian(send("GET", "/no/such/route", "", "ru"), "404");
  expect_russian(send("GET", "/v1/entry-length", "", "ru"), "405");
  expect_russian(send("POST", "/v1/entry-length", "{}", "ru", "text/plain"), "415");
  expect_russian(send("POST", "/v1/entry-length", R"({"a":1,"a":2})", "ru"), "400");
  expect_english(send("GET", "/no/such/route", "", "de, fr;q=0.5"), "404 in an unknown language");
}

bool varies_by_language(const Answer& answer) {
  for (const std::string& vary : answer.vary) {
    if (vary.find("Accept-Language") != std::string::npos) return true;
  }
  return false;
}

// A cache between client and service must not hand a Russian problem to an English client.
TEST(ProblemLanguage, NegotiatedProblemsVaryByAcceptLanguage) {
  const std::vector<std::pair<std::string, std::string>> refused = {
      {"POST /v1/roughness/groove-wall", R"({"feed_mm": -1})"},
      {"POST /v1/roughness/groove-wall", "{"},
      {"GET /v1/nope", ""},
      {"GET /v1/roughness/groove-wall", ""},
  };
  for (const auto& [what, body] : refused) {
    const std::string method = what.substr(0, what.find(' '));
    const std::string path = what.substr(what.find(' ') + 1);
    for (const char* language : {"ru", "en", ""}) {
      const Answer answer = send(method, path, body, language);
      EXPECT_GE(answer.status, 400) << what;
      EXPECT_TRUE(varies_by_language(answer)) << what << " (" << language << ")";
    }
  }
  const Answer plain = send("GET", "/healthz", "", "ru");
  EXPECT_EQ(plain.status, 200);
  EXPECT_FALSE(varies_by_language(plain)) << "an answer in no language";
}

TEST(ProblemLanguage, ErrorsCarryTheirCodeAndParameters) {
  const Answer answer = send("POST", "/v1/polygon-hole/gcode",
                             R"({"faces": 13, "inscribed_diameter_mm": 16, "depth_mm": 5,
                                 "step_down_mm": 1, "spindle_speed_rpm": 500})",
                             "");
  ASSERT_EQ(answer.status, 422) << answer.body;
  const json& error = answer.body.at("errors").at(0);
  EXPECT_EQ(error.at("pointer"), "/faces");
  EXPECT_EQ(error.at("code"), "out_of_range");
  EXPECT_EQ(error.at("minimum"), 3);
  EXPECT_EQ(error.at("maximum"), 12);
  EXPECT_EQ(error.at("detail"), "must be in [3, 12]");
  EXPECT_EQ(answer.body.at("detail"), "faces must be in [3, 12]");
}

}  // namespace
}  // namespace cutcalc::testing
