// POST /v1/program-time through its handler, no server (machine-time.md sections 2, 4 and 6):
// the request's pointers, the answer's members, a refused program's line, column and word, an
// axis the machine does not describe, the profile.

#include "api/machine_time/program_time_endpoint.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "api/json_endpoint.h"
#include "support/endpoint_probe.h"

namespace cutcalc::testing {
namespace {

using nlohmann::json;

const EndpointProbe kProgramTimeEndpoint{"/v1/program-time",
                                         &api::machine_time::handle_program_time};

json router_axes() {
  return {{"x", {{"max_velocity_mm_per_min", 12000}, {"max_acceleration_mm_per_s2", 1000}}},
          {"y", {{"max_velocity_mm_per_min", 12000}, {"max_acceleration_mm_per_s2", 1000}}},
          {"z", {{"max_velocity_mm_per_min", 8000}, {"max_acceleration_mm_per_s2", 600}}}};
}

json square_program() {
  return {{"program", "G21 G90 G17 G61.1\nF4000\nG1 X60\nG1 Y60\nG1 X0\nG1 Y0\nM2\n"},
          {"machine", {{"axes", router_axes()}, {"max_feed_mm_per_min", 12000}}}};
}

TEST(ProgramTimeEndpoint, AnswersEveryMemberOfSection6) {
  const api::ApiResponse response = kProgramTimeEndpoint.answer(square_program());
  ASSERT_EQ(response.status, 200) << response.body;
  const json body = parsed(response);
  for (const char* key :
       {"estimated_time_min", "nominal_time_min", "feed_time_min", "rapid_time_min",
        "dwell_time_min", "dynamics_time_min", "blocks", "moves", "feed_length_mm",
        "rapid_length_mm", "rotary_deg", "slowest_blocks", "warnings"}) {
    EXPECT_TRUE(body.contains(key)) << key;
  }
  EXPECT_FALSE(body.contains("profile"));
  EXPECT_EQ(body["moves"], 4);
  EXPECT_EQ(body["blocks"], 7);  // every line with a word, M2 too
  EXPECT_NEAR(body["nominal_time_min"].get<double>(), 240.0 / 4000.0, 1e-12);
  EXPECT_NEAR(body["feed_length_mm"].get<double>(), 240.0, 1e-9);
  EXPECT_NEAR(body["dynamics_time_min"].get<double>(),
              body["estimated_time_min"].get<double>() - body["nominal_time_min"].get<double>(),
              1e-12);
  ASSERT_FALSE(body["slowest_blocks"].empty());
  EXPECT_EQ(body["slowest_blocks"][0]["limited_by"], "acceleration");
}

TEST(ProgramTimeEndpoint, ProfileHasTheAskedNumberOfPoints) {
  const api::ApiResponse response =
      kProgramTimeEndpoint.answer(with(square_program(), "profile_points", 7));
  ASSERT_EQ(response.status, 200) << response.body;
  const json body = parsed(response);
  ASSERT_EQ(body["profile"].size(), 7U);
  EXPECT_EQ(body["profile"][0]["t_min"], 0.0);
  EXPECT_NEAR(body["profile"][6]["t_min"].get<double>(), body["estimated_time_min"].get<double>(),
              1e-12);
}

TEST(ProgramTimeEndpoint, RequestPointers) {
  EXPECT_EQ(kProgramTimeEndpoint.pointers(without(square_program(), "program")), only("/program"));
  EXPECT_EQ(kProgramTimeEndpoint.pointers(with(square_program(), "program", 5)), only("/program"));
  EXPECT_EQ(kProgramTimeEndpoint.pointers(without(square_program(), "machine")), only("/machine"));
  EXPECT_EQ(kProgramTimeEndpoint.pointers(with(square_program(), "dialect", "heidenhain")),
            only("/dialect"));
  EXPECT_EQ(kProgramTimeEndpoint.pointers(with(square_program(), "profile_points", 1)),
            only("/profile_points"));
  EXPECT_EQ(kProgramTimeEndpoint.pointers(with(square_program(), "profile_points", 2001)),
            only("/profile_points"));
  EXPECT_EQ(kProgramTimeEndpoint.pointers(with(square_program(), "extra", 1)), only("/extra"));
  json no_axes = square_program();
  no_axes["machine"].erase("axes");
  EXPECT_EQ(kProgramTimeEndpoint.pointers(no_axes), only("/machine/axes"));
  json half_axis = square_program();
  half_axis["machine"]["axes"]["x"].erase("max_acceleration_mm_per_s2");
  EXPECT_EQ(kProgramTimeEndpoint.pointers(half_axis),
            only("/machine/axes/x/max_acceleration_mm_per_s2"));
  json servo = square_program();
  servo["machine"]["servo_period_ms"] = 0.05;
  EXPECT_EQ(kProgramTimeEndpoint.pointers(servo), only("/machine/servo_period_ms"));
  json rotary_in_mm = square_program();
  rotary_in_mm["machine"]["axes"]["c"] = {{"max_velocity_mm_per_min", 1},
                                          {"max_acceleration_mm_per_s2", 1}};
  EXPECT_EQ(kProgramTimeEndpoint.pointers(rotary_in_mm),
            (std::set<std::string>{"/machine/axes/c/max_velocity_deg_per_min",
                                   "/machine/axes/c/max_acceleration_deg_per_s2",
                                   "/machine/axes/c/max_velocity_mm_per_min",
                                   "/machine/axes/c/max_acceleration_mm_per_s2"}));
}

TEST(ProgramTimeEndpoint, RefusedWordNamesItsLineColumnAndWord) {
  const api::ApiResponse response = kProgramTimeEndpoint.answer(
      with(square_program(), "program", "G21 G90\n#1=5\nG1 X#1 F1000\nM2\n"));
  ASSERT_EQ(response.status, 422) << response.body;
  const json error = parsed(response)["errors"][0];
  EXPECT_EQ(error["pointer"], "/program");
  EXPECT_EQ(error["code"], "gcode_parameter");
  EXPECT_EQ(error["line"], 2);
  EXPECT_EQ(error["column"], 1);
  EXPECT_EQ(error["word"], "#1");
  EXPECT_NE(parsed(response)["detail"].get<std::string>().find("line 2, column 1"),
            std::string::npos);
}

TEST(ProgramTimeEndpoint, CutterCompensationIsRefused) {
  const api::ApiResponse response = kProgramTimeEndpoint.answer(
      with(square_program(), "program", "G21 G90\nG41 D1\nG1 X10 F100\nM2\n"));
  ASSERT_EQ(response.status, 422) << response.body;
  EXPECT_EQ(parsed(response)["errors"][0]["code"], "gcode_cutter_compensation");
  EXPECT_EQ(parsed(response)["errors"][0]["line"], 2);
}

TEST(ProgramTimeEndpoint, AxisTheMachineDoesNotDescribeIsNamed) {
  json request = with(square_program(), "program", "G21 G90\nF1000\nG1 X10\nG1 C90\nM2\n");
  const api::ApiResponse response = kProgramTimeEndpoint.answer(request);
  ASSERT_EQ(response.status, 422) << response.body;
  const json error = parsed(response)["errors"][0];
  EXPECT_EQ(error["pointer"], "/machine/axes");
  EXPECT_EQ(error["code"], "axis_not_described");
  EXPECT_EQ(error["axis"], "c");
  EXPECT_EQ(error["line"], 4);
}

TEST(ProgramTimeEndpoint, MachineWithoutAxesIsRefused) {
  json request = square_program();
  request["machine"].erase("axes");
  request["machine"]["kind"] = "lathe";
  EXPECT_EQ(kProgramTimeEndpoint.pointers(request), only("/machine/axes"));
}

}  // namespace
}  // namespace cutcalc::testing
