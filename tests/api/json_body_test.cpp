// parse_json_body: the plain parse that serves valid bodies must give the library's own document,
// and everything it gives up on must still get the strict parse's exact problem.

#include "api/json_body.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <variant>

namespace cutcalc::api {
namespace {

nlohmann::json parsed(const std::string& body) {
  auto result = parse_json_body(body);
  if (auto* problem = std::get_if<Problem>(&result)) {
    ADD_FAILURE() << body << " was refused: "
                  << (problem->detail ? static_cast<int>(problem->detail->code) : -1);
    return nullptr;
  }
  return std::get<nlohmann::json>(result);
}

Problem refused(const std::string& body) {
  auto result = parse_json_body(body);
  if (auto* problem = std::get_if<Problem>(&result)) {
    return *problem;
  }
  ADD_FAILURE() << body << " was accepted";
  return Problem{};
}

std::string nested_arrays(int levels) {
  return std::string(static_cast<std::size_t>(levels), '[') + "1" +
         std::string(static_cast<std::size_t>(levels), ']');
}

TEST(JsonBody, ValidDocumentsEqualTheLibrarysParse) {
  for (const std::string body : {
           R"({"a": 1, "b": -2, "c": 18446744073709551615, "d": 2.5e-3, "e": "x\u00e9\n"})",
           R"({"entry": {"contour": "straight", "width_mm": 60}, "flags": [true, false, null]})",
           R"([{"a": [1, {"b": [2, 3]}]}, {"a": []}, {}, [], [[{"c": {}}]]])",
           R"("just a string")",
           "42",
           "null",
           R"(  {"spaces": [ 1 , 2 ] }  )",
       }) {
    EXPECT_EQ(parsed(body), nlohmann::json::parse(body)) << body;
  }
}

TEST(JsonBody, RepeatedKeyInANestedObjectIsNamed) {
  const Problem problem = refused(R"({"entry": {"contour": "straight", "contour": "wall"}})");
  EXPECT_EQ(problem.kind, ProblemKind::malformed_json);
  ASSERT_TRUE(problem.detail.has_value());
  EXPECT_EQ(problem.detail->code, ErrorCode::duplicate_key);
  EXPECT_EQ(problem.detail->params.value("key", ""), "contour");
}

TEST(JsonBody, SameKeyInSiblingObjectsIsNoRepeat) {
  EXPECT_EQ(parsed(R"([{"a": 1}, {"a": 2}, {"b": {"a": 3}, "a": 4}])").size(), 3U);
}

TEST(JsonBody, NestingUpToTheLimitParsesAndBeyondIsRefused) {
  EXPECT_EQ(parsed(nested_arrays(kMaxJsonDepth)),
            nlohmann::json::parse(nested_arrays(kMaxJsonDepth)));
  const Problem problem = refused(nested_arrays(kMaxJsonDepth + 1));
  ASSERT_TRUE(problem.detail.has_value());
  EXPECT_EQ(problem.detail->code, ErrorCode::too_deeply_nested);
}

TEST(JsonBody, NumbersBeyondADoubleReadAsNaNAndTheRestAsSent) {
  // NaN is what the field reader reports as not_finite at the field's own pointer, beside the
  // errors of every other field (a body stopped at its first overflow hid them).
  const nlohmann::json document =
      parsed(R"({"entry": {"width_mm": [1, 1e400]}, "b": -1E+999, "s": "1e400", "n": 2})");
  EXPECT_TRUE(std::isnan(document["entry"]["width_mm"][1].get<double>()));
  EXPECT_EQ(document["entry"]["width_mm"][0], 1);
  EXPECT_TRUE(std::isnan(document["b"].get<double>()));
  EXPECT_EQ(document["s"], "1e400");  // inside a string: text, not a number
  EXPECT_EQ(document["n"], 2);
}

TEST(JsonBody, MalformedTextAfterAnOverflowIsMalformedWhereItStands) {
  const Problem problem = refused(R"({"a": 1e400, "b": 1,})");
  EXPECT_EQ(problem.kind, ProblemKind::malformed_json);
  ASSERT_TRUE(problem.detail.has_value());
  EXPECT_EQ(problem.detail->code, ErrorCode::invalid_json);
  const Problem same_place = refused(R"({"a": 0    , "b": 1,})");
  ASSERT_TRUE(same_place.detail.has_value());
  EXPECT_EQ(problem.detail->params, same_place.detail->params);
}

TEST(JsonBody, RepeatedKeyAfterAnOverflowIsStillNamed) {
  const Problem problem = refused(R"({"a": 1e400, "a": 2})");
  ASSERT_TRUE(problem.detail.has_value());
  EXPECT_EQ(problem.detail->code, ErrorCode::duplicate_key);
}

TEST(JsonBody, TrailingGarbageAndBadUtf8AreMalformed) {
  for (const std::string& body :
       {std::string(R"({"a": 1} x)"), std::string("{\"a\xff\": 1}"), std::string(R"({"a": 1,})")}) {
    const Problem problem = refused(body);
    EXPECT_EQ(problem.kind, ProblemKind::malformed_json) << body;
    ASSERT_TRUE(problem.detail.has_value());
    EXPECT_EQ(problem.detail->code, ErrorCode::invalid_json) << body;
  }
}

// A string of `bytes` bytes of G-code-like text as it appears inside a JSON string (escapes
// included), long enough to be taken out of the body before the parse.
std::string long_text(std::size_t bytes, const std::string& line = "G1 X10.000 Y-2.500\\n") {
  std::string text;
  while (text.size() < bytes) text += line;
  return text;
}

TEST(JsonBody, LongStringValuesEqualTheLibrarysParse) {
  const std::string program = long_text(200 * 1024);
  const std::string escapes = long_text(70 * 1024, R"(a\"b\\c\/d\b\f\n\r\t )");
  for (const std::string& body : {
           R"({"program":")" + program + R"(","dialect":"fanuc"})",
           R"({"a":[")" + escapes + R"(", "short", ")" + program + R"("], "b": {"c": ")" + program +
               R"("}, "d": "x"})",
           // Not taken: a long key, \u escapes, bytes above 0x7f (the library decides those).
           R"({")" + program + R"(": 1, "k": ")" + program + R"("})",
           R"({"u": ")" + program + R"(\u00e9\ud83d\ude00", "v": ")" + program + R"("})",
           "{\"w\": \"" + program + "\xc3\xa9\"}",
       }) {
    EXPECT_EQ(parsed(body), nlohmann::json::parse(body)) << body.substr(0, 80);
  }
}

TEST(JsonBody, LongStringBodiesStillGetTheStrictParsesProblems) {
  const std::string program = long_text(100 * 1024);
  const Problem repeated = refused(R"({"program":")" + program + R"(","program":"x"})");
  ASSERT_TRUE(repeated.detail.has_value());
  EXPECT_EQ(repeated.detail->code, ErrorCode::duplicate_key);
  for (const std::string& body : {
           R"({"program":")" + program + "\x01" + R"("})",  // a raw control character
           R"({"program":")" + program + R"(\q"})",         // an escape JSON has not
           R"({"program":")" + program + R"(" "x"})",       // a missing comma
           R"({"program":")" + program,                     // unterminated
       }) {
    const Problem problem = refused(body);
    ASSERT_TRUE(problem.detail.has_value());
    EXPECT_EQ(problem.detail->code, ErrorCode::invalid_json);
  }
}

}  // namespace
}  // namespace cutcalc::api
