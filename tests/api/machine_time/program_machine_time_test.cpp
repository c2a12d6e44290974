// machine_time on the endpoints that write a program (machine-time.md sections 2, 6 and 7): with
// machine.axes, the answer's machine_time is POST /v1/program-time's answer on the program text
// it returns; the text/plain program ends with the estimate; program.path_control writes the mode
// in each dialect; /v1/main-time, which writes no program, refuses axes.

#include <gtest/gtest.h>

#include <string>

#include "api/entry/main_time_endpoint.h"
#include "api/entry/main_time_program_endpoint.h"
#include "api/grooving/grooving_cycle_endpoint.h"
#include "api/lathe_flat/lathe_flat_endpoint.h"
#include "api/machine_time/program_time_endpoint.h"
#include "api/polygon/polygon_hole_endpoint.h"
#include "support/endpoint_probe.h"
#include "support/test_server.h"

namespace cutcalc::testing {
namespace {

using nlohmann::json;

json axis(double velocity, double acceleration, bool rotary = false) {
  return {{rotary ? "max_velocity_deg_per_min" : "max_velocity_mm_per_min", velocity},
          {rotary ? "max_acceleration_deg_per_s2" : "max_acceleration_mm_per_s2", acceleration}};
}

json mill_machine() {
  return {{"axes",
           {{"x", axis(12000, 1000)},
            {"y", axis(12000, 1000)},
            {"z", axis(8000, 600)},
            {"c", axis(18000, 3600, true)}}},
          {"max_feed_mm_per_min", 12000}};
}

json lathe_machine() {
  return {{"axes",
           {{"x", axis(10000, 1500)}, {"z", axis(12000, 1500)}, {"c", axis(21600, 3600, true)}}},
          {"max_spindle_rpm", 4000}};
}

// The first reference request of `file` that the endpoint answers 200.
json first_request(const std::string& file) {
  const json document =
      load_reference(file);  // kept: a range-for over a temporary's member dangles
  for (const json& c : document.at("cases")) {
    if (c.at("expect").value("status", 200) == 200) return c.at("request");
  }
  return json::object();
}

struct Endpoint {
  const char* path;
  api::JsonHandler handler;
  const char* reference;
  bool lathe;
};

const Endpoint kProgramEndpoints[] = {
    {"/v1/main-time/program", &api::entry::handle_main_time_program, "main-time-program.json",
     false},
    {"/v1/polygon-hole/gcode", &api::polygon::handle_polygon_hole, "polygon-hole.json", false},
    {"/v1/grooving/cycle", &api::grooving::handle_grooving_cycle, "next/grooving-cycle.json", true},
    {"/v1/lathe-flat", &api::lathe_flat::handle_lathe_flat, "next/lathe-flat.json", true},
};

const EndpointProbe kProgramTime{"/v1/program-time", &api::machine_time::handle_program_time};

TEST(ProgramMachineTime, EqualsProgramTimeOnTheProgramItAnswers) {
  for (const Endpoint& endpoint : kProgramEndpoints) {
    SCOPED_TRACE(endpoint.path);
    const EndpointProbe probe{endpoint.path, endpoint.handler};
    json request = first_request(endpoint.reference);
    request["machine"] = endpoint.lathe ? lathe_machine() : mill_machine();
    const api::ApiResponse response = probe.answer(request);
    ASSERT_EQ(response.status, 200) << response.body;
    const json body = parsed(response);
    ASSERT_TRUE(body.contains("machine_time")) << response.body;
    json timing = {{"program", body.at("program")},
                   {"dialect", body.value("dialect", "linuxcnc")},
                   {"machine", request.at("machine")}};
    if (endpoint.lathe) timing["machine"]["kind"] = "lathe";
    const api::ApiResponse timed = kProgramTime.answer(timing);
    ASSERT_EQ(timed.status, 200) << timed.body;
    const json expected = parsed(timed);
    for (const char* key : {"estimated_time_min", "nominal_time_min", "feed_length_mm"}) {
      const double want = expected.at(key).get<double>();
      EXPECT_NEAR(body["machine_time"][key].get<double>(), want, 1e-9 * std::max(1.0, want)) << key;
    }
    EXPECT_GT(body["machine_time"]["estimated_time_min"].get<double>(), 0.0);
  }
}

TEST(ProgramMachineTime, AbsentWithoutAxes) {
  for (const Endpoint& endpoint : kProgramEndpoints) {
    SCOPED_TRACE(endpoint.path);
    const EndpointProbe probe{endpoint.path, endpoint.handler};
    const api::ApiResponse response = probe.answer(first_request(endpoint.reference));
    ASSERT_EQ(response.status, 200) << response.body;
    EXPECT_FALSE(parsed(response).contains("machine_time"));
  }
}

TEST(ProgramMachineTime, PlainTextProgramEndsWithTheEstimate) {
  const Endpoint& endpoint = kProgramEndpoints[0];
  const EndpointProbe probe{endpoint.path, endpoint.handler};
  json request = first_request(endpoint.reference);
  request["machine"] = mill_machine();
  const api::ApiResponse text = probe.answer(request, "text/plain");
  ASSERT_EQ(text.status, 200) << text.body;
  const std::string::size_type at = text.body.rfind("MACHINE TIME ");
  ASSERT_NE(at, std::string::npos) << text.body;
  const double minutes = std::stod(text.body.substr(at + 13));
  const double estimated =
      parsed(probe.answer(request))["machine_time"]["estimated_time_min"].get<double>();
  EXPECT_NEAR(minutes, estimated, 0.0005);
}

TEST(ProgramMachineTime, AnAxisTheMachineLacksIsRefused) {
  const Endpoint& endpoint = kProgramEndpoints[0];
  const EndpointProbe probe{endpoint.path, endpoint.handler};
  json request = first_request(endpoint.reference);
  request["machine"] = {{"axes", {{"x", axis(12000, 1000)}, {"y", axis(12000, 1000)}}}};
  const api::ApiResponse response = probe.answer(request);
  ASSERT_EQ(response.status, 422) << response.body;
  EXPECT_EQ(parsed(response)["errors"][0]["pointer"], "/machine/axes");
  EXPECT_EQ(parsed(response)["errors"][0]["axis"], "z");
}

TEST(ProgramMachineTime, PolygonSpindleSpeedPrintingAsZeroIsRefusedNotTimed) {
  // Found by the property step: S0.0000 left the G95 blocks with no feed (a 500 with axes).
  const Endpoint& polygon = kProgramEndpoints[1];
  const EndpointProbe probe{polygon.path, polygon.handler};
  json request = first_request(polygon.reference);
  request["spindle_speed_rpm"] = 0.00001;
  request["machine"] = mill_machine();
  EXPECT_EQ(probe.codes(request), std::set<std::string>{"word_prints_as_zero"});
  EXPECT_EQ(probe.pointers(request), std::set<std::string>{"/spindle_speed_rpm"});
}

TEST(ProgramMachineTime, MainTimeWritesNoProgramSoRefusesAxes) {
  const EndpointProbe probe{"/v1/main-time", &api::entry::handle_main_time};
  json request = first_request("main-time.json");
  request["machine"] = mill_machine();
  EXPECT_EQ(probe.pointers(request), std::set<std::string>{"/machine/axes"});
}

std::string program_of(const Endpoint& endpoint, json request) {
  const EndpointProbe probe{endpoint.path, endpoint.handler};
  const api::ApiResponse response = probe.answer(request);
  EXPECT_EQ(response.status, 200) << response.body;
  return parsed(response).value("program", "");
}

TEST(ProgramPathControl, StatesTheModeAfterTheWorkOffsetInEachDialect) {
  const Endpoint& pass = kProgramEndpoints[0];
  json request = first_request(pass.reference);
  const auto with_control = [&](const char* dialect, json control) {
    json r = request;
    r["program"] = r.value("program", json::object());
    r["program"]["dialect"] = dialect;
    r["program"]["path_control"] = std::move(control);
    return program_of(pass, r);
  };
  EXPECT_NE(with_control("linuxcnc", {{"mode", "exact_stop"}}).find("G54\nG61.1\n"),
            std::string::npos);
  EXPECT_NE(with_control("linuxcnc", {{"mode", "exact_path"}}).find("G54\nG61\n"),
            std::string::npos);
  EXPECT_NE(with_control("linuxcnc", {{"mode", "blend"}, {"tolerance_mm", 0.02}})
                .find("G54\nG64 P0.0200\n"),
            std::string::npos);
  EXPECT_NE(with_control("fanuc", {{"mode", "exact_stop"}}).find("G54\nG61\n"), std::string::npos);
  const std::string fanuc_blend =
      with_control("fanuc", {{"mode", "blend"}, {"tolerance_mm", 0.02}});
  EXPECT_NE(fanuc_blend.find("G54\nG64\n(BLEND TOLERANCE 0.020 MM"), std::string::npos)
      << fanuc_blend;
  EXPECT_NE(with_control("sinumerik", {{"mode", "exact_stop"}}).find("G54\nG60\n"),
            std::string::npos);
  EXPECT_NE(with_control("sinumerik", {{"mode", "blend"}, {"tolerance_mm", 0.02}})
                .find("G54\nG641 ADIS=0.020\n"),
            std::string::npos);
}

TEST(ProgramPathControl, PolygonBlendsWithinItsFitToleranceByDefault) {
  const Endpoint& polygon = kProgramEndpoints[1];
  json request = first_request(polygon.reference);
  request["tolerance_mm"] = 0.005;
  request["program"] = {{"path_control", {{"mode", "blend"}}}};
  EXPECT_NE(program_of(polygon, request).find("\nG64 P0.0050\n"), std::string::npos);
}

TEST(ProgramPathControl, ExactStopTimesSlowerThanTheDefaultBlend) {
  const Endpoint& polygon = kProgramEndpoints[1];
  const EndpointProbe probe{polygon.path, polygon.handler};
  json request = first_request(polygon.reference);
  request["machine"] = mill_machine();
  const double blended =
      parsed(probe.answer(request))["machine_time"]["estimated_time_min"].get<double>();
  request["program"] = {{"path_control", {{"mode", "exact_stop"}}}};
  const double stopped =
      parsed(probe.answer(request))["machine_time"]["estimated_time_min"].get<double>();
  EXPECT_GT(stopped, blended);
}

TEST(ProgramPathControl, ToleranceOnlyWithBlend) {
  const Endpoint& pass = kProgramEndpoints[0];
  const EndpointProbe probe{pass.path, pass.handler};
  json request = first_request(pass.reference);
  request["program"] = {{"path_control", {{"mode", "exact_stop"}, {"tolerance_mm", 0.1}}}};
  EXPECT_EQ(probe.pointers(request), std::set<std::string>{"/program/path_control/tolerance_mm"});
  request["program"] = {{"path_control", {{"tolerance_mm", 0.1}}}};
  EXPECT_EQ(probe.pointers(request), std::set<std::string>{"/program/path_control/mode"});
}

}  // namespace
}  // namespace cutcalc::testing
