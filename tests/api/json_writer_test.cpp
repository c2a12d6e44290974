// JsonWriter: answers written straight to text must read byte for byte as nlohmann's dump() of
// the same document, and must never let a NaN or an infinity pass unnoticed.

#include "api/json_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "api/entry/entry_length_endpoint.h"
#include "support/reference_cases.h"

namespace cutcalc::api {
namespace {

TEST(JsonWriter, NumbersReadAsDumpWritesThem) {
  for (const double value :
       {0.0, -0.0, 12.0, 10.017452406437283, 0.1 + 0.2, 1e-5, 0.0001, 1e15, 1e16, 1e17, 123456789.0,
        -2.5e-300, 1.7976931348623157e308, 5e-324, std::nextafter(1.0, 2.0)}) {
    JsonWriter out;
    out.begin_object();
    out.member("v", value);
    out.end_object();
    nlohmann::json document = nlohmann::json::object();
    document["v"] = value;
    const JsonText text = std::move(out).finish();
    EXPECT_EQ(text.text, document.dump()) << value;
    EXPECT_TRUE(text.all_finite);
  }
}

TEST(JsonWriter, NestedObjectsWordsAndDocumentsReadAsADump) {
  const nlohmann::json inner = {{"a", {1.5, 2, "x"}}, {"b", nullptr}};
  JsonWriter out;
  out.begin_object();
  out.key("first");
  out.begin_object();
  out.end_object();
  out.member("m", 1.0);
  out.key("n");
  out.begin_object();
  out.member("x_mm", 12.0);
  out.key("y");
  out.word("nose_arc");
  out.end_object();
  out.key("o");
  out.document(inner);
  out.member("z", -3.25);
  out.end_object();
  const nlohmann::json expected = {{"first", nlohmann::json::object()},
                                   {"m", 1.0},
                                   {"n", {{"x_mm", 12.0}, {"y", "nose_arc"}}},
                                   {"o", inner},
                                   {"z", -3.25}};
  EXPECT_EQ(std::move(out).finish().text, expected.dump());
}

TEST(JsonWriter, NonFiniteNumbersMarkTheAnswerUnfit) {
  for (const double bad :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    JsonWriter out;
    out.begin_object();
    out.member("v", bad);
    out.end_object();
    EXPECT_FALSE(std::move(out).finish().all_finite);
  }
  JsonWriter nested;
  nested.begin_object();
  nested.key("d");
  nested.document({{"v", -std::numeric_limits<double>::infinity()}});
  nested.end_object();
  EXPECT_FALSE(std::move(nested).finish().all_finite);
}

// Every reference request that entry-length answers: the text is what a document would dump
// (members in key order, numbers as dump() writes them), with and without exit and scheme.
TEST(JsonWriter, EntryLengthAnswersReadAsADump) {
  int answered = 0;
  for (const auto& reference : testing::load_cases("entry-length.json")) {
    for (const bool scheme : {false, true}) {
      nlohmann::json request = reference.data.at("request");
      request["include_scheme"] = scheme;
      const HandlerOutcome outcome = entry::handle_entry_length(request);
      const auto* text = std::get_if<JsonText>(&outcome);
      if (text == nullptr) {
        continue;  // a problem: not written by the writer
      }
      ++answered;
      EXPECT_TRUE(text->all_finite);
      EXPECT_EQ(text->text, nlohmann::json::parse(text->text).dump())
          << reference.data.value("id", "");
    }
  }
  EXPECT_GE(answered, 20);
}

}  // namespace
}  // namespace cutcalc::api
