// The catalogue of error codes and messages: one row per code, a Russian sentence for every English
// one with the same parameters, and openapi.yaml's ErrorCode enum listing exactly the codes that
// errors[] can carry.

#include "api/error_catalogue.h"

#include <gtest/gtest.h>

#include <regex>
#include <set>
#include <string>

#include "support/project_contract.h"

namespace cutcalc::api {
namespace {

using nlohmann::json;

std::set<std::string> placeholders(const std::string& text) {
  static const std::regex kPlaceholder(R"(\{([a-z_]+)\})");
  std::set<std::string> names;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), kPlaceholder);
       it != std::sregex_iterator(); ++it) {
    names.insert((*it)[1]);
  }
  return names;
}

bool has_cyrillic(const std::string& text) {
  // UTF-8 lead bytes 0xD0 and 0xD1 start the basic Cyrillic letters.
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte == 0xD0 || byte == 0xD1) return true;
  }
  return false;
}

TEST(ErrorCatalogue, EveryCodeHasADistinctSnakeCaseName) {
  static const std::regex kSnakeCase("[a-z]+(_[a-z]+)*");
  std::set<std::string_view> names;
  for (const ErrorCode code : all_error_codes()) {
    const std::string name(code_name(code));
    EXPECT_TRUE(std::regex_match(name, kSnakeCase)) << name;
    EXPECT_TRUE(names.insert(code_name(code)).second) << "twice: " << name;
  }
  EXPECT_GT(names.size(), 40U);
}

TEST(ErrorCatalogue, EveryMessageHasARussianSentenceWithTheSameParameters) {
  // Unfilled templates: a placeholder shows as itself when its parameter is missing.
  for (const ErrorCode code : all_error_codes()) {
    const std::string en = render_message(code, json::object(), Language::en);
    const std::string ru = render_message(code, json::object(), Language::ru);
    EXPECT_FALSE(en.empty()) << code_name(code);
    EXPECT_FALSE(has_cyrillic(en)) << code_name(code) << ": " << en;
    EXPECT_TRUE(has_cyrillic(ru)) << code_name(code) << ": " << ru;
    EXPECT_EQ(placeholders(en), placeholders(ru)) << code_name(code);
  }
}

TEST(ErrorCatalogue, ParametersFillTheSentence) {
  EXPECT_EQ(
      render_message(ErrorCode::out_of_range, {{"minimum", 3}, {"maximum", 12}}, Language::en),
      "must be in [3, 12]");
  EXPECT_EQ(render_message(ErrorCode::out_of_range,
                           {{"exclusive_minimum", 0}, {"exclusive_maximum", 90}}, Language::ru),
            "должно лежать в интервале (0, 90)");
  EXPECT_EQ(render_message(ErrorCode::not_one_of, {{"allowed", {"up", "down"}}}, Language::en),
            "must be one of: up, down");
  EXPECT_EQ(render_message(ErrorCode::below_resolution, {{"minimum", 1e-6}}, Language::en),
            "must be >= 1e-06 (smaller values are below any machine's resolution)");
}

TEST(ErrorCatalogue, OpenApiEnumListsExactlyTheCodesOfErrorsLists) {
  const json& document = test_support::project_contract().document();
  const json& listed = document.at("components").at("schemas").at("ErrorCode").at("enum");
  std::set<std::string> documented(listed.begin(), listed.end());
  std::set<std::string> in_code;
  for (const ErrorCode code : all_error_codes()) {
    if (in_errors_list(code)) in_code.emplace(code_name(code));
  }
  EXPECT_EQ(documented, in_code);
}

}  // namespace
}  // namespace cutcalc::api
