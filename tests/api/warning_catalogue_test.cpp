// The catalogue of program warnings: a sentence in each language for every code of
// domain/program/warning_codes.def, the answer's warnings[] speaking the request's language
// (Accept-Language, as problem details do) while the detail stays the program comment's English,
// and the page keeping no sentences of its own.

#include "api/warning_catalogue.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "support/route_paths.h"
#include "support/test_server.h"

#ifndef CUTCALC_WEB_DIR
#error "CUTCALC_WEB_DIR must be defined"
#endif

namespace cutcalc::api {
namespace {

using domain::program::warning_name;
using domain::program::WarningCode;
using nlohmann::json;

bool has_cyrillic(std::string_view text) {
  // UTF-8 lead bytes 0xD0 and 0xD1 start the basic Cyrillic letters.
  return std::any_of(text.begin(), text.end(), [](char c) {
    const auto byte = static_cast<unsigned char>(c);
    return byte == 0xD0 || byte == 0xD1;
  });
}

TEST(WarningCatalogue, EveryCodeHasAnEnglishAndARussianSentence) {
  std::set<std::string_view> english;
  for (const WarningCode code : all_warning_codes()) {
    const std::string_view en = warning_message(code, Language::en);
    const std::string_view ru = warning_message(code, Language::ru);
    EXPECT_FALSE(en.empty()) << warning_name(code);
    EXPECT_FALSE(has_cyrillic(en)) << warning_name(code) << ": " << en;
    EXPECT_TRUE(has_cyrillic(ru)) << warning_name(code) << ": " << ru;
    EXPECT_TRUE(english.insert(en).second) << "two codes say " << en;
  }
  EXPECT_EQ(all_warning_codes().size(), 14U);
}

TEST(WarningCatalogue, EveryCodeIsFoundByItsWireName) {
  for (const WarningCode code : all_warning_codes()) {
    EXPECT_EQ(warning_code_named(warning_name(code)), code) << warning_name(code);
  }
  EXPECT_FALSE(warning_code_named("phase_slip").has_value());
}

TEST(WarningCatalogue, MessagesReachTheListsOfMemberObjectsAndKeepTheDetail) {
  json answer = json::parse(R"({
    "warnings": [{"code": "units_assumed", "detail": "read as mm"}],
    "machine_time": {"warnings": [{"code": "untimed_stop", "detail": "M0"}]},
    "profile": [{"warnings": [{"code": "untimed_stop", "detail": "not a list of this answer"}]}]})");
  EXPECT_TRUE(add_warning_messages(answer, Language::ru));
  EXPECT_EQ(answer["warnings"][0]["message"].get<std::string>(),
            warning_message(WarningCode::units_assumed, Language::ru));
  EXPECT_EQ(answer["warnings"][0]["detail"].get<std::string>(), "read as mm");
  EXPECT_EQ(answer["machine_time"]["warnings"][0]["message"].get<std::string>(),
            warning_message(WarningCode::untimed_stop, Language::ru));
  // Arrays are not searched: they hold no warnings lists of the answer and may be long.
  EXPECT_FALSE(answer["profile"][0]["warnings"][0].contains("message"));
  json no_warnings = {{"main_time_min", 1.5}};
  EXPECT_FALSE(add_warning_messages(no_warnings, Language::ru));
  EXPECT_FALSE(no_warnings.contains("warnings"));
}

// The worked example of the pass program with a machine that both limits trip.
std::string program_over_the_limits() {
  const json reference = testing::load_reference("main-time-program.json");
  for (const json& c : reference.at("cases")) {
    if (c.at("id") != "prog-P-WORKED") continue;
    json request = c.at("request");
    request["machine"] = {{"max_spindle_rpm", 500}, {"max_feed_mm_per_min", 100}};
    return request.dump();
  }
  ADD_FAILURE() << "prog-P-WORKED is missing";
  return "{}";
}

struct WarnedAnswer {
  json warnings;
  std::string content_language;
  std::string vary;
};

WarnedAnswer post_in(const std::string& accept_language,
                     const std::string& path = testing::kMainTimeProgramPath) {
  json request = json::parse(program_over_the_limits());
  if (path != testing::kMainTimeProgramPath) request.erase("program");
  auto client = testing::TestServer::shared().client();
  const auto reply = client->Post(path, {{"Accept-Language", accept_language}}, request.dump(),
                                  "application/json");
  if (!reply || reply->status != 200) {
    ADD_FAILURE() << "no 200 answer";
    return {};
  }
  std::string vary;
  for (std::size_t i = 0; i < reply->get_header_value_count("Vary"); ++i) {
    vary += reply->get_header_value("Vary", i) + ",";
  }
  return {json::parse(reply->body).at("warnings"), reply->get_header_value("Content-Language"),
          vary};
}

TEST(WarningLanguage, AcceptLanguageRuGivesRussianMessagesAndTheSameCodesAndDetails) {
  const WarnedAnswer english = post_in("en");
  const WarnedAnswer russian = post_in("ru-RU,ru;q=0.9,en;q=0.5");
  ASSERT_EQ(russian.warnings.size(), 2U);
  ASSERT_EQ(english.warnings.size(), russian.warnings.size());
  for (std::size_t i = 0; i < russian.warnings.size(); ++i) {
    const json& ru = russian.warnings[i];
    const json& en = english.warnings[i];
    EXPECT_EQ(ru.at("code"), en.at("code"));
    EXPECT_EQ(ru.at("detail"), en.at("detail")) << "the detail is the comment line's English";
    const auto code = warning_code_named(ru.at("code").get<std::string>());
    ASSERT_TRUE(code.has_value());
    EXPECT_TRUE(has_cyrillic(ru.at("message").get<std::string>())) << ru;
    EXPECT_FALSE(has_cyrillic(en.at("message").get<std::string>())) << en;
    EXPECT_EQ(ru.at("message").get<std::string>(), warning_message(*code, Language::ru));
    EXPECT_EQ(en.at("message").get<std::string>(), warning_message(*code, Language::en));
  }
  EXPECT_EQ(russian.content_language, "ru");
  EXPECT_EQ(english.content_language, "en");
  EXPECT_NE(russian.vary.find("Accept-Language"), std::string::npos) << russian.vary;
}

// An answer that is no program (a JSON object, not streamed) speaks the language too.
TEST(WarningLanguage, MainTimeWarningsAreRussianForAcceptLanguageRu) {
  const WarnedAnswer russian = post_in("ru", "/v1/main-time");
  ASSERT_EQ(russian.warnings.size(), 2U);
  for (const json& warning : russian.warnings) {
    EXPECT_TRUE(has_cyrillic(warning.at("message").get<std::string>())) << warning;
    EXPECT_FALSE(has_cyrillic(warning.at("detail").get<std::string>())) << warning;
  }
  EXPECT_EQ(russian.content_language, "ru");
}

// The page shows the server's sentence (warnings[].message): no catalogue of the page holds a
// warning's sentence, so the one list (warning_codes.def) and its catalogue are the only ones.
TEST(WarningLanguage, ThePageKeepsNoWarningSentencesOfItsOwn) {
  int scripts = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(CUTCALC_WEB_DIR)) {
    if (entry.path().extension() != ".js") continue;
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    const std::string source = text.str();
    for (const char* key : {"'warning.", "\"warning.", "`warning."}) {
      EXPECT_EQ(source.find(key), std::string::npos) << entry.path() << " holds " << key;
    }
    ++scripts;
  }
  EXPECT_GT(scripts, 20);
}

}  // namespace
}  // namespace cutcalc::api
