// Hostile and broken request bodies: each gets its 4xx with a problem body, never a crash, a 500,
// a NaN or an infinity, and the server keeps serving afterwards.

#include <gtest/gtest.h>

#include <string>

#include "support/reference_compare.h"
#include "support/test_server.h"

namespace cutcalc::testing {
namespace {

const std::string kEntry = "/v1/entry-length";
const std::string kMainTime = "/v1/main-time";

const char* kValidEntry =
    R"({"cutter_diameter_mm": 20, "entry": {"contour": "straight", "width_mm": 60}})";

void expect_problem(const JsonReply& reply, int status) {
  EXPECT_EQ(reply.status, status) << reply.body;
  EXPECT_EQ(reply.content_type, "application/problem+json");
  ASSERT_TRUE(reply.json.is_object()) << reply.body;
  EXPECT_EQ(reply.json.value("status", 0), status);
  EXPECT_TRUE(reply.json.contains("type"));
  EXPECT_TRUE(reply.json.contains("title"));
  EXPECT_FALSE(reply.json.value("detail", std::string()).empty());
  EXPECT_TRUE(reply.json.contains("errors") && reply.json["errors"].is_array());
}

void expect_still_serving() {
  const JsonReply reply = post(kEntry, kValidEntry);
  EXPECT_EQ(reply.status, 200) << reply.body;
}

TEST(BadInput, EmptyBodyIsMalformed) {
  expect_problem(post(kEntry, ""), 400);
  expect_still_serving();
}

TEST(BadInput, TextThatIsNotJsonIsMalformed) {
  expect_problem(post(kEntry, "cutter_diameter_mm=20"), 400);
  expect_problem(post(kEntry, "{\"cutter_diameter_mm\": 20,"), 400);
  expect_still_serving();
}

TEST(BadInput, WrongContentTypeIsUnsupported) {
  expect_problem(post(kEntry, kValidEntry, "text/plain"), 415);
  expect_problem(post(kEntry, kValidEntry, "application/x-www-form-urlencoded"), 415);
  expect_still_serving();
}

TEST(BadInput, JsonContentTypeWithCharsetIsAccepted) {
  EXPECT_EQ(post(kEntry, kValidEntry, "application/json; charset=utf-8").status, 200);
}

TEST(BadInput, OneMebibyteBodyIsTooLarge) {
  const std::string huge = R"({"pad": ")" + std::string(1024 * 1024, 'x') + R"("})";
  const JsonReply reply = post(kEntry, huge);
  expect_problem(reply, 413);
  expect_still_serving();
}

TEST(BadInput, BodyJustUnderTheLimitIsParsed) {
  // 60 KiB of whitespace around a valid object: within 64 KiB, so it is read and answered.
  const std::string padded = std::string(60 * 1024, ' ') + kValidEntry;
  EXPECT_EQ(post(kEntry, padded).status, 200);
}

TEST(BadInput, DeeplyNestedJsonIsRejectedWithoutRecursion) {
  const std::string deep = std::string(10000, '[') + std::string(10000, ']');
  expect_problem(post(kEntry, deep), 400);
  const std::string deep_objects = [] {
    std::string text;
    for (int i = 0; i < 10000; ++i) {
      text += R"({"a":)";
    }
    text += "1" + std::string(10000, '}');
    return text;
  }();
  expect_problem(post(kEntry, deep_objects), 400);
  expect_still_serving();
}

TEST(BadInput, StringsForNumbersNameTheField) {
  const JsonReply reply =
      post(kEntry,
           R"({"cutter_diameter_mm": "20", "entry": {"contour": "straight", "width_mm": "60"}})");
  expect_problem(reply, 422);
  EXPECT_TRUE(problem_names_pointer(reply.json, "/cutter_diameter_mm"));
  EXPECT_TRUE(problem_names_pointer(reply.json, "/entry/width_mm"));
}

TEST(BadInput, NanLiteralIsNotJson) {
  expect_problem(
      post(kEntry,
           R"({"cutter_diameter_mm": NaN, "entry": {"contour": "straight", "width_mm": 60}})"),
      400);
}

TEST(BadInput, NumberTooLargeForADoubleNamesItsField) {
  const JsonReply reply = post(
      kEntry, R"({"cutter_diameter_mm": 1e400, "entry": {"contour": "straight", "width_mm": 60}})");
  expect_problem(reply, 422);
  EXPECT_TRUE(problem_names_pointer(reply.json, "/cutter_diameter_mm")) << reply.body;
}

TEST(BadInput, NumberTooLargeForADoubleHidesNoOtherFieldError) {
  const JsonReply reply = post("/v1/roughness/bore-milling",
                               R"({"bore_radius_mm": 1e400, "cutter_radius_mm": 32.4, "teeth": 1001,
                                   "feed_per_rev_mm": -1e999, "milling": "up", "zz": 1})");
  expect_problem(reply, 422);
  for (const char* pointer : {"/bore_radius_mm", "/teeth", "/feed_per_rev_mm", "/zz"}) {
    EXPECT_TRUE(problem_names_pointer(reply.json, pointer)) << pointer << ": " << reply.body;
  }
  EXPECT_EQ(reply.json["errors"].size(), 4U) << reply.body;
}

TEST(BadInput, HugeFiniteSizesAreRejectedNotOverflowed) {
  const JsonReply reply =
      post(kEntry,
           R"({"cutter_diameter_mm": 1e300, "entry": {"contour": "straight", "width_mm": 1e300}})");
  expect_problem(reply, 422);
  EXPECT_TRUE(problem_names_pointer(reply.json, "/cutter_diameter_mm"));
}

TEST(BadInput, NegativeAndZeroSizesNameEachField) {
  const JsonReply reply = post(kEntry, R"({"cutter_diameter_mm": 0, "approach_mm": -1,
      "entry": {"contour": "convex_arc", "radius_mm": -5}})");
  expect_problem(reply, 422);
  EXPECT_TRUE(problem_names_pointer(reply.json, "/cutter_diameter_mm"));
  EXPECT_TRUE(problem_names_pointer(reply.json, "/approach_mm"));
  EXPECT_TRUE(problem_names_pointer(reply.json, "/entry/radius_mm"));
  EXPECT_EQ(reply.json["errors"].size(), 3U) << reply.body;
  EXPECT_EQ(reply.json.value("detail", std::string()),
            "cutter_diameter_mm must be > 0 (and 2 more)");
}

TEST(BadInput, UnknownFieldsAreRejectedAtAnyLevel) {
  const JsonReply reply = post(kEntry, R"({"cutter_diameter_mm": 20, "cutter_radius_mm": 10,
      "entry": {"contour": "straight", "width_mm": 60, "radius_mm": 5}})");
  expect_problem(reply, 422);
  EXPECT_TRUE(problem_names_pointer(reply.json, "/cutter_radius_mm"));
  EXPECT_TRUE(problem_names_pointer(reply.json, "/entry/radius_mm"));
}

TEST(BadInput, DuplicateKeysAreMalformed) {
  expect_problem(post(kEntry, R"({"cutter_diameter_mm": 20, "cutter_diameter_mm": 30,
      "entry": {"contour": "straight", "width_mm": 60}})"),
                 400);
}

TEST(BadInput, BodyThatIsNotAnObjectPointsAtTheRoot) {
  for (const char* body : {"[]", "42", "\"text\"", "null", "true"}) {
    const JsonReply reply = post(kEntry, body);
    expect_problem(reply, 422);
    EXPECT_TRUE(problem_names_pointer(reply.json, "")) << body;
  }
}

TEST(BadInput, WrongTypesForObjectsAndChoices) {
  const JsonReply reply = post(kEntry, R"({"cutter_diameter_mm": 20, "entry": [1, 2]})");
  expect_problem(reply, 422);
  EXPECT_TRUE(problem_names_pointer(reply.json, "/entry"));
  const JsonReply contour = post(kEntry, R"({"cutter_diameter_mm": 20, "entry": {"contour": 7}})");
  EXPECT_TRUE(problem_names_pointer(contour.json, "/entry/contour"));
}

TEST(BadInput, WallIsAnExitOnlyContour) {
  const JsonReply reply =
      post(kEntry, R"({"cutter_diameter_mm": 20, "entry": {"contour": "wall", "width_mm": 60}})");
  expect_problem(reply, 422);
  EXPECT_TRUE(problem_names_pointer(reply.json, "/entry/contour"));
}

TEST(BadInput, PathLengthsWithoutAnExitAreRejected) {
  const JsonReply reply = post(kEntry, R"({"cutter_diameter_mm": 20, "length_mm": 100,
      "entry": {"contour": "straight", "width_mm": 60}})");
  expect_problem(reply, 422);
  // Said once, with its reason: not also as an unknown field.
  ASSERT_EQ(reply.json["errors"].size(), 1U) << reply.body;
  EXPECT_EQ(reply.json["errors"][0].value("pointer", ""), "/length_mm");
  EXPECT_EQ(reply.json["errors"][0].value("code", ""), "requires_field");
}

TEST(BadInput, MainTimeNeedsExactlyOneSpeed) {
  const std::string base = R"({"cutter_diameter_mm": 20, "teeth": 4, "feed_per_tooth_mm": 0.05,
      "length_mm": 100, "entry": {"contour": "straight", "width_mm": 60},
      "exit": {"contour": "straight", "width_mm": 60},
      "allowance": {"width_mm": 20, "width_of_cut_mm": 20, "depth_mm": 2, "depth_of_cut_mm": 2})";
  const JsonReply neither = post(kMainTime, base + "}");
  expect_problem(neither, 422);
  EXPECT_TRUE(problem_names_pointer(neither.json, ""));
  const JsonReply both =
      post(kMainTime, base + R"(, "spindle_speed_rpm": 1000, "cutting_speed_m_per_min": 100})");
  EXPECT_TRUE(problem_names_pointer(both.json, ""));
  const JsonReply one = post(kMainTime, base + R"(, "spindle_speed_rpm": 1000})");
  EXPECT_EQ(one.status, 200) << one.body;
}

// The choice between alternatives is listed beside every other field error, the program
// options' own rules included (it was said only when nothing else was wrong).
TEST(BadInput, MissingSpeedIsListedBesideOtherFieldErrors) {
  const std::string base = R"({"cutter_diameter_mm": -20, "teeth": 4, "feed_per_tooth_mm": 0.05,
      "length_mm": 100, "entry": {"contour": "straight", "width_mm": 60},
      "exit": {"contour": "straight", "width_mm": 60},
      "allowance": {"width_mm": 20, "width_of_cut_mm": 20, "depth_mm": 2, "depth_of_cut_mm": 2})";
  const JsonReply plain = post(kMainTime, base + "}");
  EXPECT_TRUE(problem_names_pointer(plain.json, "/cutter_diameter_mm")) << plain.body;
  EXPECT_TRUE(problem_names_pointer(plain.json, "")) << plain.body;
  const JsonReply program =
      post("/v1/main-time/program",
           base + R"(, "entry_feed_factor": 0.5, "entry_feed_per_tooth_mm": 0.01,
                 "program": {"clearance_mm": 100}})");
  EXPECT_TRUE(problem_names_pointer(program.json, "/program/clearance_mm")) << program.body;
  std::size_t at_root = 0;
  for (const auto& error : program.json.at("errors")) at_root += error.at("pointer") == "" ? 1 : 0;
  EXPECT_EQ(at_root, 2U) << "no speed, and both entry feeds: " << program.body;
}

TEST(BadInput, TeethMustBeAWholeNumber) {
  const std::string body = R"({"cutter_diameter_mm": 20, "teeth": TEETH, "spindle_speed_rpm": 1000,
      "feed_per_tooth_mm": 0.05, "length_mm": 100,
      "entry": {"contour": "straight", "width_mm": 60}, "exit": {"contour": "straight", "width_mm": 60},
      "allowance": {"width_mm": 20, "width_of_cut_mm": 20, "depth_mm": 2, "depth_of_cut_mm": 2}})";
  const auto with_teeth = [&body](const std::string& teeth) {
    std::string text = body;
    text.replace(text.find("TEETH"), 5, teeth);
    return post(kMainTime, text);
  };
  EXPECT_EQ(with_teeth("2.0").status, 200);
  const JsonReply fractional = with_teeth("2.5");
  expect_problem(fractional, 422);
  EXPECT_TRUE(problem_names_pointer(fractional.json, "/teeth"));
  EXPECT_TRUE(problem_names_pointer(with_teeth("0").json, "/teeth"));
  EXPECT_TRUE(problem_names_pointer(with_teeth("1e300").json, "/teeth"));
}

TEST(BadInput, InvalidUtf8InAKeyStillGetsAProblemBody) {
  const JsonReply reply = post(kEntry,
                               "{\"cutter_diameter_mm\": 20, \"\xff\xfe\": 1, "
                               "\"entry\": {\"contour\": \"straight\", \"width_mm\": 60}}");
  EXPECT_GE(reply.status, 400);
  EXPECT_LT(reply.status, 500);
  EXPECT_EQ(reply.content_type, "application/problem+json");
  expect_still_serving();
}

}  // namespace
}  // namespace cutcalc::testing
