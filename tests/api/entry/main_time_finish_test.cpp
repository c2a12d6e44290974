// Equal passes and the finishing level (spec entry-and-main-time.md section 15) over HTTP, beyond
// the cases of next/main-time.json (replayed by tools/contract/replay.mjs): the pass program takes
// the same fields with the same errors, writes each level's feeds and the finishing S word, and
// its feed time is the main time. rs274 acceptance in every dialect: tests/gcode.

#include <gtest/gtest.h>

#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "support/program_text_rules.h"
#include "support/project_contract.h"
#include "support/reference_cases.h"
#include "support/reference_compare.h"
#include "support/route_paths.h"

namespace cutcalc::testing {
namespace {

using nlohmann::json;

constexpr const char* kProgram = "/v1/main-time/program";

json next_case(const std::string& id) {
  for (const ReferenceCase& c : load_cases("next/main-time.json")) {
    if (c.data.at("id") == id) {
      json request = c.data.at("request");
      request.erase("extra_path_mm");  // 0: the program endpoint takes it too, but only as 0
      return request;
    }
  }
  ADD_FAILURE() << id << " is missing from next/main-time.json";
  return json::object();
}

TEST(MainTimeNextReferenceFile, HoldsTheExpectedNumberOfCases) {
  EXPECT_GE(load_cases("next/main-time.json").size(), 13U);
}

void expect_problem_at(const char* path, const json& request, const std::string& pointer) {
  const JsonReply reply = post(path, request.dump());
  EXPECT_EQ(reply.status, 422) << path << " " << reply.body;
  EXPECT_TRUE(problem_names_pointer(reply.json, pointer))
      << path << " " << pointer << ": " << reply.body;
  expect_conforms(path, reply);
}

// One parser for both endpoints: every section 15 error is the same on the program endpoint.
TEST(MainTimeFinish, BothEndpointsRefuseWhatSection15Refuses) {
  const json base = next_case("MN-finish");
  for (const char* path : {kMainTimePath, kProgram}) {
    json request = base;
    request["pass_split"] = "even";
    expect_problem_at(path, request, "/pass_split");
    request = base;
    request["finish"] = 0.5;
    expect_problem_at(path, request, "/finish");
    request = base;
    request["finish"]["speed"] = 1;
    expect_problem_at(path, request, "/finish/speed");
    request = base;
    request["finish"].erase("depth_of_cut_mm");
    expect_problem_at(path, request, "/finish/depth_of_cut_mm");
    request = base;
    request["finish"]["feed_per_tooth_mm"] = 0;
    expect_problem_at(path, request, "/finish/feed_per_tooth_mm");
    request = base;
    request["finish"]["cutting_speed_m_per_min"] = -1;
    expect_problem_at(path, request, "/finish/cutting_speed_m_per_min");
    request = base;
    request["finish"]["spindle_speed_rpm"] = 1500;
    request["finish"]["cutting_speed_m_per_min"] = 200;
    expect_problem_at(path, request, "");
    request = base;
    request["finish"]["depth_of_cut_mm"] = 6;
    expect_problem_at(path, request, "/finish/depth_of_cut_mm");
    request = base;
    request.erase("entry_feed_factor");
    request["entry_feed_per_tooth_mm"] = 0.08;  // <= S_z 0.1 but > S_zf 0.05
    expect_problem_at(path, request, "/entry_feed_per_tooth_mm");
  }
}

// G8 = E41: the program's answer carries main-time's own answer, and its feed time is T_o.
TEST(MainTimeFinish, ProgramWorkingTimeIsTheMainTimeWithTheFinishingLevel) {
  for (const char* id : {"MN-finish", "MN-finish-rpm", "MN-finish-equal", "MN-worked-equal"}) {
    const json request = next_case(id);
    const JsonReply main_time = post(kMainTimePath, request.dump());
    const JsonReply program = post(kProgram, request.dump());
    ASSERT_EQ(program.status, 200) << id << " " << program.body;
    EXPECT_EQ(program.json.at("main_time"), main_time.json) << id;
    EXPECT_NEAR(program.json.at("working_time_min").get<double>(),
                main_time.json.at("main_time_min").get<double>(), 1e-12)
        << id;
  }
}

// The lines of `program` that match `pattern`.
std::vector<std::string> lines_matching(const std::string& program, const std::regex& pattern) {
  std::vector<std::string> out;
  std::istringstream in(program);
  std::string line;
  while (std::getline(in, line)) {
    if (std::regex_search(line, pattern)) out.push_back(line);
  }
  return out;
}

// Section 15: level j uses its own S_m1,j, S_m2,j; an S{n_f} block before the finishing level;
// its default plunge feed is S_m1f. MN-finish-rpm: n 1000 -> 400/200 mm/min; n_f 1500 -> 300/150.
TEST(MainTimeFinish, ProgramWritesEachLevelsFeedsAndTheFinishingSpeed) {
  const JsonReply reply = post(kProgram, next_case("MN-finish-rpm").dump());
  ASSERT_EQ(reply.status, 200) << reply.body;
  const std::string program = reply.json.at("program").get<std::string>();
  const auto speeds = lines_matching(program, std::regex("^S"));
  ASSERT_EQ(speeds.size(), 2U) << program;
  EXPECT_EQ(speeds[0], "S1000.0000 M3");
  EXPECT_EQ(speeds[1], "S1500.0000");
  const std::size_t finishing = program.find("\nS1500.0000\n");
  // Roughing: plunge and entry at S_m1 = 200, steady at 400; finishing: 150 and 300.
  const std::string roughing_part = program.substr(0, finishing);
  const std::string finishing_part = program.substr(finishing);
  EXPECT_NE(roughing_part.find("F200.0000"), std::string::npos);
  EXPECT_NE(roughing_part.find("F400.0000"), std::string::npos);
  EXPECT_EQ(roughing_part.find("F150.0000"), std::string::npos);
  EXPECT_NE(finishing_part.find("F150.0000"), std::string::npos);
  EXPECT_NE(finishing_part.find("F300.0000"), std::string::npos);
  EXPECT_EQ(finishing_part.find("F400.0000"), std::string::npos);
  // The finishing level's passes: N1 = 2 traverses after the S block, all at Z -5 (= -H).
  EXPECT_EQ(lines_matching(finishing_part, std::regex("^G1 Z-5\\.0000")).size(), 2U)
      << finishing_part;
}

// Without a finishing speed n_f = n: no S block beyond the first.
TEST(MainTimeFinish, ProgramWithoutAFinishingSpeedSetsTheSpindleOnce) {
  const JsonReply reply = post(kProgram, next_case("MN-finish").dump());
  ASSERT_EQ(reply.status, 200) << reply.body;
  const std::string program = reply.json.at("program").get<std::string>();
  EXPECT_EQ(lines_matching(program, std::regex("^S")).size(), 1U) << program;
}

TEST(MainTimeFinish, ProgramsKeepTheTextRulesOfEveryDialectAndUnit) {
  for (const char* id : {"MN-finish-rpm", "MN-finish-equal"}) {
    for (const char* dialect : {"linuxcnc", "fanuc", "sinumerik"}) {
      for (const char* units : {"mm", "inch"}) {
        json request = next_case(id);
        request["program"] = {{"dialect", dialect}, {"units", units}, {"coolant", "flood"}};
        const JsonReply reply = post(kProgram, request.dump());
        ASSERT_EQ(reply.status, 200) << reply.body;
        expect_text_rules(reply.json.at("program").get<std::string>(), dialect);
      }
    }
  }
}

// Section 5: the finishing level's speed and feeds are limits' business too.
TEST(MainTimeFinish, MachineLimitsSeeTheFinishingSpeed) {
  json request = next_case("MN-finish-rpm");  // n 1000, n_f 1500
  request["machine"] = {{"max_spindle_rpm", 1200}};
  const JsonReply reply = post(kMainTimePath, request.dump());
  ASSERT_EQ(reply.status, 200) << reply.body;
  ASSERT_EQ(reply.json.at("warnings").size(), 1U) << reply.body;
  EXPECT_EQ(reply.json.at("warnings")[0].at("code"), "spindle_over_limit");
}

}  // namespace
}  // namespace cutcalc::testing
