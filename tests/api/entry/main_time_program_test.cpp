// POST /v1/main-time/program over HTTP (its reference cases are replayed by
// tools/contract/replay.mjs, ctest ReferenceReplay.EveryCaseOverHttp): the plain-text answer, the
// text rules of every dialect (spec programs.md section 3) on every reference program, and the
// errors the reference file does not cover. rs274 acceptance and the times on the text:
// tests/gcode.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <regex>
#include <set>
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

TEST(MainTimeProgramReferenceFile, HoldsTheExpectedNumberOfCases) {
  EXPECT_GE(load_cases("main-time-program.json").size(), 30U);
}

json worked_example() {
  for (const ReferenceCase& c : load_cases("main-time-program.json")) {
    if (c.data.at("id") == "prog-P-WORKED") return c.data.at("request");
  }
  ADD_FAILURE() << "prog-P-WORKED is missing";
  return {};
}

TEST(MainTimeProgram, PlainTextAnswerIsTheProgramWithTheDialectsFileName) {
  json request = worked_example();
  request["program"] = {{"dialect", "sinumerik"}, {"name", "FACE_01"}};
  const JsonReply as_json = post(kMainTimeProgramPath, request.dump());
  auto client = TestServer::shared().client();
  const auto reply = client->Post(kMainTimeProgramPath, {{"Accept", "text/plain"}}, request.dump(),
                                  "application/json");
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->status, 200);
  EXPECT_EQ(reply->get_header_value("Content-Type"), "text/plain; charset=us-ascii");
  EXPECT_EQ(reply->get_header_value("Content-Disposition"), "attachment; filename=\"FACE_01.MPF\"");
  EXPECT_EQ(reply->body, as_json.json.at("program").get<std::string>());
  std::map<std::string, std::string> headers;
  for (const auto& [name, value] : reply->headers) headers[name] = value;
  for (const auto& violation : test_support::project_contract().check_response_headers(
           "post", kMainTimeProgramPath, 200, headers)) {
    ADD_FAILURE() << "headers break openapi.yaml: " << violation;
  }
}

TEST(MainTimeProgram, WorkingTimeIsTheMainTimeOfMainTime) {
  json main_time_request = worked_example();
  main_time_request.erase("program");
  const JsonReply main_time = post("/v1/main-time", main_time_request.dump());
  const JsonReply program = post(kMainTimeProgramPath, worked_example().dump());
  ASSERT_EQ(program.status, 200);
  EXPECT_EQ(program.json.at("main_time"), main_time.json);
  EXPECT_NEAR(program.json.at("working_time_min").get<double>(),
              main_time.json.at("main_time_min").get<double>(), 1e-12);
}

TEST(MainTimeProgram, EveryReferenceProgramKeepsTheTextRulesOfEveryDialectAndUnit) {
  int checked = 0;
  for (const ReferenceCase& reference : load_cases("main-time-program.json")) {
    if (reference.data.at("expect").at("status") != 200) continue;
    for (const char* dialect : {"linuxcnc", "fanuc", "sinumerik"}) {
      for (const char* units : {"mm", "inch"}) {
        json request = reference.data.at("request");
        json program = {{"dialect", dialect},
                        {"units", units},
                        {"tool_number", 7},
                        {"tool_length_offset", true},
                        {"coolant", "mist"}};
        request["program"] = program;
        const JsonReply reply = post(kMainTimeProgramPath, request.dump());
        ASSERT_EQ(reply.status, 200) << reply.body;
        expect_text_rules(reply.json.at("program").get<std::string>(), dialect);
        ++checked;
      }
    }
  }
  EXPECT_GE(checked, 60);
}

TEST(MainTimeProgram, WarningsFollowTheSpecsOrderAndAreCommentLines) {
  json request = worked_example();
  request["machine"] = {{"max_spindle_rpm", 500}, {"max_feed_mm_per_min", 100}};
  request["program"] = {{"dialect", "fanuc"}};
  const JsonReply reply = post(kMainTimeProgramPath, request.dump());
  ASSERT_EQ(reply.status, 200);
  const json& warnings = reply.json.at("warnings");
  ASSERT_EQ(warnings.size(), 2U);
  EXPECT_EQ(warnings[0].at("code"), "spindle_over_limit");
  EXPECT_EQ(warnings[1].at("code"), "feed_over_limit");
  const std::string program = reply.json.at("program").get<std::string>();
  EXPECT_LT(program.find("(WARNING SPINDLE_OVER_LIMIT"), program.find("(WARNING FEED_OVER_LIMIT"));
  EXPECT_LT(program.find("(WARNING FEED_OVER_LIMIT"), program.find("G21"));
}

TEST(MainTime, AnswersMachineLimitWarningsAndAnEmptyListWithoutLimits) {
  json request = worked_example();
  request.erase("program");
  EXPECT_EQ(post("/v1/main-time", request.dump()).json.at("warnings"), json::array());
  request["machine"] = {{"max_feed_mm_per_min", 300}};
  const JsonReply reply = post("/v1/main-time", request.dump());
  ASSERT_EQ(reply.status, 200);
  ASSERT_EQ(reply.json.at("warnings").size(), 1U);
  EXPECT_EQ(reply.json.at("warnings")[0].at("code"), "feed_over_limit");
}

void expect_program_problem_at(const json& request, const std::string& pointer) {
  const JsonReply reply = post(kMainTimeProgramPath, request.dump());
  EXPECT_EQ(reply.status, 422) << reply.body;
  EXPECT_TRUE(problem_names_pointer(reply.json, pointer)) << pointer << ": " << reply.body;
  expect_conforms(kMainTimeProgramPath, reply);
}

TEST(MainTimeProgram, RefusesWhatSection6Refuses) {
  const json base = worked_example();
  const auto with = [&](const json& program) {
    json request = base;
    request["program"] = program;
    return request;
  };
  expect_program_problem_at(with({{"dialect", "sinumerik"}, {"work_offset", "G58"}}),
                            "/program/work_offset");
  expect_program_problem_at(with({{"coolant", "fog"}}), "/program/coolant");
  expect_program_problem_at(with({{"dialect", "fanuc"}, {"program_number", 8000}}),
                            "/program/program_number");
  expect_program_problem_at(with({{"name", "cutcalc"}}), "/program/name");
  expect_program_problem_at(with({{"dialect", "sinumerik"}, {"name", "CYCLE800"}}),
                            "/program/name");
  expect_program_problem_at(with({{"dialect", "sinumerik"}, {"name", "A1"}}), "/program/name");
  expect_program_problem_at(with({{"name", "COM3"}}), "/program/name");
  expect_program_problem_at(with({{"tool_number", 2.5}}), "/program/tool_number");
  expect_program_problem_at(with({{"safe_z_mm", 0}}), "/program/safe_z_mm");
  expect_program_problem_at(with({{"clearance_mm", -1}}), "/program/clearance_mm");
  expect_program_problem_at(with({{"plunge_feed_mm_per_min", 0}}),
                            "/program/plunge_feed_mm_per_min");
  expect_program_problem_at(with({{"tool_length_offset", "yes"}}), "/program/tool_length_offset");
  json machine = base;
  machine["machine"] = {{"max_feed_mm_per_min", -5}};
  expect_program_problem_at(machine, "/machine/max_feed_mm_per_min");
  // A feed that prints as zero: S_m1 = 1e-6 S_m2 = 0.0004 mm/min at 3 decimals.
  json tiny = with({{"dialect", "fanuc"}});
  tiny["entry_feed_factor"] = 0.000001;
  expect_program_problem_at(tiny, "");
  // Over 200 000 blocks: 10 000 lateral x 10 depth passes.
  json huge = base;
  huge["program"] = json::object();
  huge["entry"] = {{"contour", "straight"}, {"width_mm", 100}};
  huge["exit"] = {{"contour", "straight"}, {"width_mm", 100}};
  huge["cutter_diameter_mm"] = 10;
  huge["allowance"] = {
      {"width_mm", 100}, {"width_of_cut_mm", 0.01}, {"depth_mm", 10}, {"depth_of_cut_mm", 1}};
  expect_program_problem_at(huge, "");
}

// extra_path_mm > 0 is a field rule of this endpoint (programs.md 1.2): listed with every other
// field error, not answered alone after them.
TEST(MainTimeProgram, ExtraPathIsAFieldErrorListedWithTheOthers) {
  json request = worked_example();
  request["extra_path_mm"] = 5;
  request["program"] = {{"coolant", "fog"}};
  request["teeth"] = 0;
  const JsonReply reply = post(kMainTimeProgramPath, request.dump());
  ASSERT_EQ(reply.status, 422) << reply.body;
  EXPECT_EQ(reply.json.at("type"), "urn:cutcalc:problem:invalid-input");
  std::map<std::string, std::string> code_at;
  for (const json& error : reply.json.at("errors")) {
    code_at[error.at("pointer").get<std::string>()] = error.at("code").get<std::string>();
  }
  EXPECT_EQ(code_at["/extra_path_mm"], "program_needs_straight_path") << reply.body;
  EXPECT_EQ(code_at["/program/coolant"], "not_one_of") << reply.body;
  EXPECT_TRUE(code_at.count("/teeth")) << reply.body;
  // Alone it is the same field error.
  json alone = worked_example();
  alone["extra_path_mm"] = 0.5;
  const JsonReply only = post(kMainTimeProgramPath, alone.dump());
  ASSERT_EQ(only.status, 422) << only.body;
  EXPECT_EQ(only.json.at("type"), "urn:cutcalc:problem:invalid-input");
  ASSERT_EQ(only.json.at("errors").size(), 1U) << only.body;
  EXPECT_EQ(only.json.at("errors")[0].at("pointer"), "/extra_path_mm");
  EXPECT_EQ(only.json.at("errors")[0].at("code"), "program_needs_straight_path");
  EXPECT_EQ(only.json.at("detail"), "extra_path_mm must be 0 (a program needs a straight path)");
  expect_conforms(kMainTimeProgramPath, reply);
}

}  // namespace
}  // namespace cutcalc::testing
