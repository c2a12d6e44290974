// README.md and openapi.yaml state the request limits in words; the numbers and the 413 problem
// they show must be the ones service/http_limits.h sets and the server answers.

#include "service/http_limits.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/project_contract.h"
#include "support/test_server.h"

#ifndef CUTCALC_OPENAPI_PATH
#error "CUTCALC_OPENAPI_PATH must be defined"
#endif

namespace cutcalc::testing {
namespace {

using nlohmann::json;

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Line breaks and indentation as single spaces: prose wraps anywhere.
std::string one_line(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const bool space = c == ' ' || c == '\n';
    if (!(space && (out.empty() || out.back() == ' '))) out.push_back(space ? ' ' : c);
  }
  return out;
}

const std::string& readme() {
  static const std::string text =
      one_line(read_text(std::filesystem::path(CUTCALC_OPENAPI_PATH).parent_path() / "README.md"));
  return text;
}

const std::string& openapi_text() {
  static const std::string text = one_line(read_text(CUTCALC_OPENAPI_PATH));
  return text;
}

std::string kib(std::size_t bytes) { return std::to_string(bytes / 1024) + " KiB"; }

TEST(HttpLimits, ReadmeStatesTheBodyLimitAndTheShutdownWait) {
  const service::HttpLimits limits;
  ASSERT_EQ(limits.max_body_bytes % 1024, 0U);
  EXPECT_NE(readme().find("a body over " + kib(limits.max_body_bytes) + " gets `413`"),
            std::string::npos);
  const auto wait_s = std::chrono::duration_cast<std::chrono::seconds>(limits.request_timeout);
  EXPECT_NE(readme().find("in flight (up to " + std::to_string(wait_s.count()) + " s)"),
            std::string::npos);
}

TEST(HttpLimits, OpenApiStatesTheHeadAndBodyLimits) {
  const service::HttpLimits limits;
  ASSERT_EQ(limits.max_head_bytes % 1024, 0U);
  EXPECT_NE(openapi_text().find("a head over " + kib(limits.max_head_bytes) + ","),
            std::string::npos);
  EXPECT_NE(openapi_text().find("The body is over the limit, " + kib(limits.max_body_bytes) +
                                " by default"),
            std::string::npos);
}

// The documented 413 example is what the server says to a body one byte over the limit; a body
// at the limit is read.
TEST(HttpLimits, OpenApiPayloadTooLargeExampleIsTheServersAnswer) {
  const service::HttpLimits limits;
  const json document = test_support::project_contract().document();
  const json& example = document.at("components")
                            .at("responses")
                            .at("PayloadTooLarge")
                            .at("content")
                            .at("application/problem+json")
                            .at("example");
  const std::string object = R"({"cutter_diameter_mm": 20})";
  const auto padded = [&](std::size_t bytes) {
    return std::string(bytes - object.size(), ' ') + object;
  };
  const JsonReply over =
      post(example.at("instance").get<std::string>(), padded(limits.max_body_bytes + 1));
  ASSERT_EQ(over.status, 413) << over.body;
  ASSERT_TRUE(over.json.is_object()) << over.body;
  ASSERT_TRUE(example.is_object()) << example.dump();
  for (const char* member : {"type", "title", "status", "detail", "errors"}) {
    EXPECT_EQ(over.json.at(member), example.at(member)) << member;
  }
  const JsonReply at_limit =
      post(example.at("instance").get<std::string>(), padded(limits.max_body_bytes));
  EXPECT_NE(at_limit.status, 413) << at_limit.body;
  EXPECT_NE(at_limit.status, 0);
}

}  // namespace
}  // namespace cutcalc::testing
