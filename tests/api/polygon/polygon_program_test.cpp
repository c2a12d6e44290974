// POST /v1/polygon-hole/gcode with a `program` object and `machine` (spec programs.md sections
// 2-5): every reference hole in every dialect and unit (contract, text rules, file name, the
// printed deviation), the order of the warnings and their comment lines, and the errors.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/program_text_rules.h"
#include "support/project_contract.h"
#include "support/reference_cases.h"
#include "support/reference_compare.h"
#include "support/route_paths.h"

namespace cutcalc::testing {
namespace {

using nlohmann::json;

std::vector<json> polygon_ok_requests() {
  std::vector<json> requests;
  for (const ReferenceCase& c : load_cases("polygon-hole.json")) {
    if (c.data.at("expect").at("status") == 200) requests.push_back(c.data.at("request"));
  }
  return requests;
}

JsonReply post_checked(const json& request) {
  const JsonReply reply = post(kPolygonGcodePath, request.dump());
  expect_conforms(kPolygonGcodePath, reply);
  return reply;
}

TEST(PolygonProgram, WithoutAProgramObjectTheAnswerNamesTodaysProgram) {
  for (const json& request : polygon_ok_requests()) {
    if (request.contains("program")) {
      continue;  // a next/ case asks for a dialect
    }
    const JsonReply reply = post_checked(request);
    ASSERT_EQ(reply.status, 200);
    EXPECT_EQ(reply.json.at("dialect"), "linuxcnc");
    EXPECT_EQ(reply.json.at("units"), "mm");
    EXPECT_EQ(reply.json.at("file_name").get<std::string>().rfind("polygon-hole-N", 0), 0U);
    EXPECT_FALSE(reply.json.contains("printed_path_deviation_mm"));
    EXPECT_EQ(reply.json.at("program").get<std::string>().rfind("%\n(CUTCALC POLYGON HOLE N", 0),
              0U);
  }
}

TEST(PolygonProgram, EveryReferenceHoleInEveryDialectAndUnitKeepsTheTextRules) {
  int checked = 0;
  for (const json& base : polygon_ok_requests()) {
    for (const char* dialect : {"linuxcnc", "fanuc", "sinumerik"}) {
      for (const char* units : {"mm", "inch"}) {
        json request = base;
        request["program"] = {{"dialect", dialect}, {"units", units},
                              {"tool_number", 4},   {"tool_length_offset", true},
                              {"coolant", "flood"}, {"name", "HOLE_1"}};
        if (request.contains("safe_z_mm")) {
          request["program"]["safe_z_mm"] = request["safe_z_mm"];
          request.erase("safe_z_mm");
        }
        SCOPED_TRACE(request.dump());
        const JsonReply reply = post_checked(request);
        ASSERT_EQ(reply.status, 200) << reply.body;
        const std::string program = reply.json.at("program").get<std::string>();
        expect_text_rules(program, dialect);
        EXPECT_EQ(reply.json.at("dialect"), dialect);
        EXPECT_EQ(reply.json.at("units"), units);
        const std::string file = reply.json.at("file_name").get<std::string>();
        EXPECT_EQ(file, std::string(dialect) == "fanuc"       ? "O0001.nc"
                        : std::string(dialect) == "sinumerik" ? "HOLE_1.MPF"
                                                              : "HOLE_1.ngc");
        EXPECT_GE(reply.json.at("printed_path_deviation_mm").get<double>(), 0.0);
        EXPECT_NE(program.find("CUTCALC POLYGON HOLE N"), std::string::npos);
        ++checked;
      }
    }
  }
  EXPECT_GE(checked, 30);
}

TEST(PolygonProgram, PrintedDeviationAtFourDecimalsInMmIsTheFittedOneWithinRounding) {
  for (const json& base : polygon_ok_requests()) {
    json request = base;
    request["program"] = {{"decimals", 4}};
    const JsonReply reply = post_checked(request);
    ASSERT_EQ(reply.status, 200);
    const double printed = reply.json.at("printed_path_deviation_mm").get<double>();
    const double fitted = reply.json.at("max_path_deviation_mm").get<double>();
    // Each printed coordinate is within 0.5e-4 mm of the fitted one; the spiral interpolation of
    // a rounded arc moves a point by at most a few of those.
    EXPECT_NEAR(printed, fitted, 3e-4) << request.dump();
  }
}

TEST(PolygonProgram, InchProgramSaysItsCommentNumbersAreInMm) {
  for (const char* dialect : {"linuxcnc", "fanuc", "sinumerik"}) {
    json request = polygon_ok_requests().front();
    request["program"] = {{"dialect", dialect}, {"units", "inch"}};
    const JsonReply reply = post_checked(request);
    ASSERT_EQ(reply.status, 200) << reply.body;
    const std::string program = reply.json.at("program").get<std::string>();
    const std::size_t said = program.find("NUMBERS IN THESE COMMENTS IN MM, PROGRAM UNITS INCH");
    ASSERT_NE(said, std::string::npos) << dialect << "\n" << program.substr(0, 600);
    EXPECT_LT(said, program.find("G20")) << dialect << ": said before the unit is set";
    request["program"]["units"] = "mm";
    const JsonReply mm = post_checked(request);
    EXPECT_EQ(mm.json.at("program").get<std::string>().find("NUMBERS IN THESE COMMENTS"),
              std::string::npos)
        << dialect;
  }
}

TEST(PolygonProgram, RoundingBeyondTheToleranceWarnsInTheSpecsOrderAndAsCommentLines) {
  json request = polygon_ok_requests().front();
  request["spindle_speed_rpm"] = 30.5;
  request["synchronization"] = "feed_per_rev";
  request["machine"] = {{"max_spindle_rpm", 10}, {"max_feed_mm_per_min", 1}};
  request["program"] = {{"dialect", "fanuc"}, {"units", "inch"}, {"decimals", 3}};
  const JsonReply reply = post_checked(request);
  ASSERT_EQ(reply.status, 200) << reply.body;
  std::vector<std::string> codes;
  for (const json& warning : reply.json.at("warnings")) codes.push_back(warning.at("code"));
  const std::vector<std::string> expected = {"spindle_over_limit", "feed_over_limit",
                                             "spindle_speed_rounded", "rounding_exceeds_tolerance",
                                             "phase_not_locked"};
  std::vector<std::string> known;
  for (const auto& code : codes) {
    if (code != "feed_exceeds_block_rate") known.push_back(code);
  }
  EXPECT_EQ(known, expected);
  const std::string program = reply.json.at("program").get<std::string>();
  std::size_t at = 0;
  for (const std::string& code : expected) {
    std::string upper = code;
    for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    const std::size_t line = program.find("(WARNING " + upper + ":");
    ASSERT_NE(line, std::string::npos) << code;
    EXPECT_GT(line, at) << code << " out of order";
    at = line;
  }
  // The plain-text answer is the same program (its warnings are in it already).
  auto client = TestServer::shared().client();
  const auto text = client->Post(kPolygonGcodePath, {{"Accept", "text/plain"}}, request.dump(),
                                 "application/json");
  ASSERT_TRUE(text);
  EXPECT_EQ(text->body, program);
  EXPECT_EQ(text->get_header_value("Content-Disposition"), "attachment; filename=\"O0001.nc\"");
}

void expect_polygon_problem_at(const json& request, const std::string& pointer) {
  const JsonReply reply = post_checked(request);
  EXPECT_EQ(reply.status, 422) << reply.body;
  EXPECT_TRUE(problem_names_pointer(reply.json, pointer)) << pointer << ": " << reply.body;
}

TEST(PolygonProgram, RefusesThePassProgramsMembersAndTwoSafeHeights) {
  const json base = polygon_ok_requests().front();
  for (const char* member : {"clearance_mm", "plunge_feed_mm_per_min", "rapid_mm_per_min"}) {
    json request = base;
    request["program"] = {{member, 1}};
    expect_polygon_problem_at(request, std::string("/program/") + member);
  }
  json both = base;
  both["safe_z_mm"] = 5;
  both["program"] = {{"safe_z_mm", 6}};
  expect_polygon_problem_at(both, "/program/safe_z_mm");
  json machine = base;
  machine["machine"] = {{"max_spindle_rpm", 0}};
  expect_polygon_problem_at(machine, "/machine/max_spindle_rpm");
  json dialect = base;
  dialect["program"] = {{"dialect", "heidenhain"}};
  expect_polygon_problem_at(dialect, "/program/dialect");
}

}  // namespace
}  // namespace cutcalc::testing
