// The JSON object whose first member is a program written as it is read (api/streamed_json.h):
// the other members after it, those computed only once the program is written last, and a number
// that is not finite among those cutting the body short instead of printing null.

#include <gtest/gtest.h>

#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "api/streamed_json.h"
#include "domain/common/text_source.h"

namespace cutcalc::api {
namespace {

std::unique_ptr<domain::TextSource> program(std::string text) {
  return std::make_unique<domain::StringSource>(std::move(text));
}

// The whole body, asked for in pieces of `piece` bytes as the engine asks.
std::string written(domain::TextSource& source, std::size_t piece = 4) {
  std::string out;
  while (source.write_next(out, piece)) {
  }
  return out;
}

TEST(StreamedJson, TheProgramComesFirstEscapedThenTheOtherMembers) {
  const auto source = json_with_streamed_string("program", program("G0 X1\n(\"A\")\n"),
                                                {{"units", "mm"}, {"blocks", 2}});
  const std::string body = written(*source);
  EXPECT_EQ(body.rfind("{\"program\":\"G0 X1\\n(\\\"A\\\")\\n\",", 0), 0U) << body;
  const auto parsed = nlohmann::json::parse(body);
  EXPECT_EQ(parsed,
            (nlohmann::json{{"program", "G0 X1\n(\"A\")\n"}, {"units", "mm"}, {"blocks", 2}}));
}

TEST(StreamedJson, MembersComputedAfterTheProgramAreAskedForOnlyOnceItIsWritten) {
  bool asked = false;
  const auto source = json_with_streamed_string("program", program(std::string(100, 'G')),
                                                {{"units", "mm"}}, [&](nlohmann::json& members) {
                                                  asked = true;
                                                  members["overcut_mm"] = 0.25;
                                                });
  std::string out;
  ASSERT_TRUE(source->write_next(out, 10));
  EXPECT_FALSE(asked) << "asked for before the program was written";
  while (source->write_next(out, 10)) {
  }
  EXPECT_TRUE(asked);
  const auto parsed = nlohmann::json::parse(out);
  EXPECT_EQ(parsed.value("overcut_mm", 0.0), 0.25);
  EXPECT_EQ(parsed.value("units", ""), "mm");
  EXPECT_TRUE(out.ends_with(",\"overcut_mm\":0.25}")) << out;
}

TEST(StreamedJson, WithNoOtherMembersTheLateOnesFollowTheProgram) {
  const auto source =
      json_with_streamed_string("program", program("M30\n"), nlohmann::json::object(),
                                [](nlohmann::json& members) { members["a"] = 1; });
  EXPECT_EQ(written(*source), "{\"program\":\"M30\\n\",\"a\":1}");
  const auto bare = json_with_streamed_string("program", program(""), nlohmann::json::object());
  EXPECT_EQ(written(*bare), "{\"program\":\"\"}");
}

TEST(StreamedJson, ANonFiniteLateMemberCutsTheBodyShort) {
  const auto source = json_with_streamed_string(
      "program", program("G1 X1\n"), {{"units", "mm"}}, [](nlohmann::json& members) {
        members["overcut_mm"] = std::numeric_limits<double>::quiet_NaN();
      });
  std::string out;
  EXPECT_THROW(
      {
        while (source->write_next(out, 1024)) {
        }
      },
      std::logic_error);
  EXPECT_EQ(out.find("null"), std::string::npos) << out;
}

}  // namespace
}  // namespace cutcalc::api
