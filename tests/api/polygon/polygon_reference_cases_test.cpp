// Replays every case of shared/reference/polygon-hole.json over HTTP: values within tolerance,
// quality bounds (expect.max / expect.min), warning codes, and the checks on the program text.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <set>
#include <sstream>

#include "support/reference_replay.h"

namespace cutcalc::testing {
namespace {

using nlohmann::json;

// polygon-hole.json: |got - want| <= abs + rel |want|.
ToleranceFn polygon_tolerance(const json& tolerance) {
  const double abs = tolerance.at("abs").get<double>();
  const double rel = tolerance.at("rel").get<double>();
  return [abs, rel](const std::string& /*key*/, double want) { return abs + rel * std::abs(want); };
}

// The value of word `letter` in a block ("X-1.2345" -> "-1.2345"), or "" when absent.
std::string word(const std::string& block, char letter) {
  const std::regex pattern(std::string("(?:^|\\s)") + letter + "(-?[0-9]+\\.[0-9]+)");
  std::smatch match;
  return std::regex_search(block, match, pattern) ? match[1].str() : std::string();
}

struct ProgramFacts {
  int arc_blocks = 0;
  std::vector<double> loop_end_z;  // Z after each loop
  std::string deepest_z;
  std::set<std::string> feed_words_g95;
  std::string g94_feed;
  std::string last_c;
};

ProgramFacts read_program(const std::string& program, int blocks_per_loop) {
  ProgramFacts facts;
  std::istringstream lines(program);
  std::string line;
  double z = 0.0;
  double deepest = 0.0;
  while (std::getline(lines, line)) {
    if (line.empty() || line[0] == '(' || line[0] == '%') {
      continue;
    }
    if (const std::string z_word = word(line, 'Z'); !z_word.empty()) {
      z = std::stod(z_word);
      if (z < deepest) {
        deepest = z;
        facts.deepest_z = z_word;
      }
    }
    if (line.rfind("G2 ", 0) == 0 || line.rfind("G3 ", 0) == 0) {
      ++facts.arc_blocks;
      if (blocks_per_loop > 0 && facts.arc_blocks % blocks_per_loop == 0) {
        facts.loop_end_z.push_back(z);
      }
      if (const std::string c = word(line, 'C'); !c.empty()) {
        facts.last_c = c;
      }
    }
    if (line.find("G95") != std::string::npos && !word(line, 'F').empty()) {
      facts.feed_words_g95.insert(word(line, 'F'));
    }
    if (line.find("G94") != std::string::npos && !word(line, 'F').empty()) {
      facts.g94_feed = word(line, 'F');
    }
  }
  return facts;
}

class PolygonReferenceCase : public ::testing::TestWithParam<ReferenceCase> {};

TEST_P(PolygonReferenceCase, ServiceAnswersWithinTheReferenceBounds) {
  const ReferenceCase& reference = GetParam();
  const json tolerance = reference.data.value("tolerance", json());
  const JsonReply reply = replay_reference_case(
      reference, tolerance.is_null() ? polygon_tolerance({{"abs", 0}, {"rel", 0}})
                                     : polygon_tolerance(tolerance));
  const json& expect = reference.data.at("expect");
  if (reply.status != 200 || !reply.json.is_object()) {
    return;
  }
  SCOPED_TRACE(reference.data.at("id").get<std::string>());
  const json upper_bounds = expect.value("max", json::object());
  const json lower_bounds = expect.value("min", json::object());
  for (const auto& [key, bound] : upper_bounds.items()) {
    EXPECT_LE(reply.json.at(key).get<double>(), bound.get<double>()) << key;
  }
  for (const auto& [key, bound] : lower_bounds.items()) {
    EXPECT_GE(reply.json.at(key).get<double>(), bound.get<double>()) << key;
  }
  std::set<std::string> codes;
  for (const auto& warning : reply.json.at("warnings")) {
    codes.insert(warning.at("code").get<std::string>());
  }
  const auto expected_codes = expect.value("warning_codes", std::vector<std::string>{});
  EXPECT_EQ(codes, std::set<std::string>(expected_codes.begin(), expected_codes.end()));

  const json checks = expect.value("program", json::object());
  const int blocks_per_loop = reply.json.at("blocks_per_loop").get<int>();
  const ProgramFacts facts =
      read_program(reply.json.at("program").get<std::string>(), blocks_per_loop);
  if (checks.contains("loops")) {
    EXPECT_EQ(facts.arc_blocks % blocks_per_loop, 0);
    EXPECT_EQ(facts.arc_blocks / blocks_per_loop, checks["loops"].get<int>());
  }
  if (checks.contains("layers")) {
    // The loops end at Z = -k depth / n, k = 1..n, and at nothing else.
    const int layers = checks["layers"].get<int>();
    const double depth = reference.data.at("request").at("depth_mm").get<double>();
    std::set<long> levels;
    for (const double z : facts.loop_end_z) {
      levels.insert(std::lround(-z / depth * layers * 1000.0));
    }
    std::set<long> expected_levels;
    for (int k = 1; k <= layers; ++k) {
      expected_levels.insert(static_cast<long>(k) * 1000);
    }
    EXPECT_EQ(levels, expected_levels);
  }
  if (checks.contains("z_min")) {
    EXPECT_EQ(facts.deepest_z, checks["z_min"].get<std::string>());
  }
  if (checks.contains("g95_flat_F")) {
    EXPECT_TRUE(facts.feed_words_g95.count(checks["g95_flat_F"].get<std::string>()) == 1)
        << "G95 F words: " << ::testing::PrintToString(facts.feed_words_g95);
  }
  if (checks.contains("g94_F")) {
    EXPECT_EQ(facts.g94_feed, checks["g94_F"].get<std::string>());
  }
  if (checks.contains("last_C")) {
    EXPECT_EQ(facts.last_c, checks["last_C"].get<std::string>());
  }
}

INSTANTIATE_TEST_SUITE_P(PolygonHole, PolygonReferenceCase,
                         ::testing::ValuesIn(load_cases("polygon-hole.json")), reference_case_name);

TEST(PolygonHoleHttp, AcceptTextPlainAnswersTheBareProgramAsAnAttachment) {
  auto client = TestServer::shared().client();
  const auto reply = client->Post(
      "/v1/polygon-hole/gcode", {{"Accept", "text/plain"}},
      R"({"faces": 4, "inscribed_diameter_mm": 16, "depth_mm": 0.1, "step_down_mm": 0.1,
          "spindle_speed_rpm": 30})",
      "application/json");
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->status, 200);
  EXPECT_EQ(reply->get_header_value("Content-Type"), "text/plain; charset=us-ascii");
  EXPECT_EQ(reply->get_header_value("Content-Disposition"),
            "attachment; filename=\"polygon-hole-N4-d16.0000.ngc\"");
  EXPECT_EQ(reply->body.rfind("%\n(CUTCALC POLYGON HOLE N4 D16.0000 A16.0000)", 0), 0U)
      << reply->body.substr(0, 200);
  EXPECT_NE(reply->body.find("(WARNING phase_not_locked: "), std::string::npos);
  EXPECT_EQ(reply->body.back(), '\n');
}

TEST(PolygonHoleHttp, ErrorsStayProblemJsonWhateverTheAcceptHeader) {
  auto client = TestServer::shared().client();
  const auto reply = client->Post("/v1/polygon-hole/gcode", {{"Accept", "text/plain"}},
                                  R"({"faces": 13})", "application/json");
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->status, 422);
  EXPECT_EQ(reply->get_header_value("Content-Type"), "application/problem+json");
}

}  // namespace
}  // namespace cutcalc::testing
