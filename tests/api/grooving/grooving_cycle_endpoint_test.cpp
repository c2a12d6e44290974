// POST /v1/grooving/cycle through its handler, no server (grooving-cycle.md sections 3.7 and 6):
// every row of the pointer table, the program members of a lathe program, unknown fields, the
// answer's members and the text/plain form with its file name.

#include "api/grooving/grooving_cycle_endpoint.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "api/json_endpoint.h"
#include "support/endpoint_probe.h"
#include "support/route_paths.h"

namespace cutcalc::testing {
namespace {

using nlohmann::json;

// The worked example's request (section 7).
json paper_groove() {
  return {{"groove_width_mm", 10.4}, {"start_diameter_mm", 220}, {"groove_depth_mm", 4.8},
          {"groove_left_z_mm", -20}, {"shift_mm", 0.4},          {"cutting_speed_m_per_min", 86},
          {"max_spindle_rpm", 1000}, {"nose_radius_mm", 0.3},    {"minor_edge_angle_deg", 2},
          {"feed_per_rev_mm", 0.12}};
}

const EndpointProbe kGroovingCycleEndpoint{kGroovingCyclePath,
                                           &api::grooving::handle_grooving_cycle};

TEST(GroovingCycleEndpoint, WorkedExampleAnswersWithEveryMemberOfSection37) {
  const api::ApiResponse response = kGroovingCycleEndpoint.answer(paper_groove());
  ASSERT_EQ(response.status, 200) << response.body;
  const json body = parsed(response);
  for (const char* key : {"tool_width_mm",
                          "shift_mm",
                          "groove_depth_mm",
                          "bottom_diameter_mm",
                          "approach_diameter_mm",
                          "revolutions",
                          "radial_revolutions",
                          "shift_revolutions",
                          "shifts",
                          "infeed_per_revolution_mm",
                          "shift_feed_mm_per_rev",
                          "final_shift_revolutions",
                          "spindle_revolutions",
                          "end_side",
                          "approach_time_min",
                          "plunge_time_min",
                          "shift_time_min",
                          "dwell_time_min",
                          "final_shift_time_min",
                          "retract_time_min",
                          "cycle_time_min",
                          "spindle_speed_at_start_rpm",
                          "spindle_speed_at_bottom_rpm",
                          "chip_thickness_mm",
                          "side_chip_thickness_mm",
                          "wall_pitch_mm",
                          "wall_rz_um",
                          "wall_rz_branch",
                          "plain_plunge_rz_um",
                          "warnings",
                          "program",
                          "file_name",
                          "dialect",
                          "units",
                          "decimals"}) {
    EXPECT_TRUE(body.contains(key)) << key;
  }
  EXPECT_EQ(body.size(), 35U) << body.dump();
  EXPECT_EQ(body.at("revolutions"), 40);
  EXPECT_EQ(body.at("shifts"), 21);
  EXPECT_EQ(body.at("end_side"), "right");
  EXPECT_NEAR(body.at("cycle_time_min").get<double>(), 0.415614, 0.5e-6);
  EXPECT_EQ(body.at("wall_rz_branch"), "nose_arc_and_minor_edge");
  EXPECT_EQ(body.at("warnings"), json::array());
  EXPECT_EQ(body.at("dialect"), "linuxcnc");
  EXPECT_EQ(body.at("units"), "mm");
  EXPECT_EQ(body.at("decimals"), 4);
  EXPECT_EQ(body.at("file_name"), "CUTCALC.ngc");
  const std::string program = body.at("program").get<std::string>();
  for (const char* line :
       {"\nG96 D1000.0000 S86.0000 M3\n", "\nG1 X220.0000 F0.1200\nG1 X219.7600\n",
        "\nG1 X219.5200 Z-19.6000 F0.4176\n", "\nG1 X210.4000 Z-20.0000 F0.4176\n", "\nG4 P0.461\n",
        "\nG1 Z-19.6000 F0.1200\n", "\nG0 X222.0000\n"}) {
    EXPECT_NE(program.find(line), std::string::npos) << line;
  }
}

TEST(GroovingCycleEndpoint, DefaultsOfSection2) {
  // dwell 1 rev, clearance 1 mm, rapid 10000 mm/min; an explicit default gives the same answer.
  json explicit_defaults = paper_groove();
  explicit_defaults["dwell_revolutions"] = 1;
  explicit_defaults["approach_clearance_mm"] = 1;
  explicit_defaults["rapid_mm_per_min"] = 10000;
  EXPECT_EQ(kGroovingCycleEndpoint.answer(explicit_defaults).body,
            kGroovingCycleEndpoint.answer(paper_groove()).body);
  // No shift and no tool width: X2 = min(0.4, W/3).
  const json body = parsed(kGroovingCycleEndpoint.answer(without(paper_groove(), "shift_mm")));
  EXPECT_NEAR(body.at("shift_mm").get<double>(), 0.4, 1e-12);
  EXPECT_NEAR(body.at("tool_width_mm").get<double>(), 10.0, 1e-12);
}

TEST(GroovingCycleEndpoint, PositiveMembersZeroNegativeOrMissingPointAtThemselves) {
  for (const char* key :
       {"groove_width_mm", "start_diameter_mm", "feed_per_rev_mm", "nose_radius_mm"}) {
    const std::string pointer = std::string("/") + key;
    EXPECT_EQ(kGroovingCycleEndpoint.pointers(with(paper_groove(), key, 0)), only(pointer)) << key;
    EXPECT_EQ(kGroovingCycleEndpoint.pointers(with(paper_groove(), key, -1)), only(pointer)) << key;
    EXPECT_EQ(kGroovingCycleEndpoint.pointers(without(paper_groove(), key)), only(pointer)) << key;
    EXPECT_EQ(kGroovingCycleEndpoint.pointers(with(paper_groove(), key, "1")), only(pointer))
        << key;
  }
}

TEST(GroovingCycleEndpoint, LeftWallZIsRequiredAndFinite) {
  EXPECT_EQ(kGroovingCycleEndpoint.pointers(without(paper_groove(), "groove_left_z_mm")),
            only("/groove_left_z_mm"));
  EXPECT_EQ(kGroovingCycleEndpoint.pointers(with(paper_groove(), "groove_left_z_mm", nullptr)),
            only("/groove_left_z_mm"));
  EXPECT_EQ(kGroovingCycleEndpoint.pointers(with(paper_groove(), "groove_left_z_mm", "-20")),
            only("/groove_left_z_mm"));
  // Any finite number, also zero and positive.
  EXPECT_EQ(kGroovingCycleEndpoint.answer(with(paper_groove(), "groove_left_z_mm", 0)).status, 200);
  EXPECT_EQ(kGroovingCycleEndpoint.answer(with(paper_groove(), "groove_left_z_mm", 35.5)).status,
            200);
}

TEST(GroovingCycleEndpoint, ExactlyOneOfBottomAndDepth) {
  EXPECT_EQ(kGroovingCycleEndpoint.pointers(with(paper_groove(), "bottom_diameter_mm", 210.4)),
            only("/bottom_diameter_mm"));
  EXPECT_EQ(kGroovingCycleEndpoint.pointers(without(paper_groove(), "groove_depth_mm")),
            only("/groove_depth_mm"));
  EXPECT_EQ(
      kGroovingCycleEndpoint
          .answer(with(without(paper_groove(), "groove_depth_mm"), "bottom_diameter_mm", 210.4))
          .status,
      200);
}

TEST(GroovingCycleEndpoint, BottomAndDepthOutOfRangePointAtThemselves) {
  const json by_bottom = without(paper_groove(), "groove_depth_mm");
  for (const double bottom : {0.0, -1.0, 220.0, 221.0}) {
    EXPECT_EQ(kGroovingCycleEndpoint.pointers(with(by_bottom, "bottom_diameter_mm", bottom)),
              only("/bottom_diameter_mm"))
        << bottom;
  }
  for (const double depth : {0.0, -1.0, 110.0, 111.0}) {
    EXPECT_EQ(kGroovingCycleEndpoint.pointers(with(paper_groove(), "groove_depth_mm", depth)),
              only("/groove_depth_mm"))
        << depth;
  }
}

TEST(GroovingCycleEndpoint, ExactlyOneOfSpindleSpeedAndCuttingSpeed) {
  EXPECT_EQ(kGroovingCycleEndpoint.pointers(with(paper_groove(), "spindle_speed_rpm", 150)),
            only("/cutting_speed_m_per_min"));
  EXPECT_EQ(kGroovingCycleEndpoint.pointers(without(paper_groove(), "cutting_speed_m_per_min")),
            only("/spindle_speed_rpm"));
  json g97 = with(without(paper_groove(), "cutting_speed_m_per_min"), "spindle_speed_rpm", 150);
  EXPECT_EQ(kGroovingCycleEndpoint.answer(g97).status, 200);
  // With n the limit is optional.
  EXPECT_EQ(kGroovingCycleEndpoint.answer(without(g97, "max_spindle_rpm")).status, 200);
}

TEST(GroovingCycleEndpoint, SpeedsAndTheLimitMustBePositiveAndTheLimitComesWithV) {
  EXPECT_EQ(kGroovingCycleEndpoint.pointers(with(paper_groove(), "cutting_speed_m_per_min", 0)),
            only("/cutting_speed_m_per_min"));
  const json g97 =
      with(without(paper_groove(), "cutting_speed_m_per_min"), "spindle_speed_rpm", 150);
  EXPECT_EQ(kGroovingCycleEndpoint.pointers(with(g97, "spindle_speed_rpm", -5)),
            only("/spindle_speed_rpm"));
  EXPECT_EQ(kGroovingCycleEndpoint.pointers(with(paper_groove(), "max_spindle_rpm", 0)),
            only("/max_spindle_rpm"));
  EXPECT_EQ(kGroovingCycleEndpoint.pointers(with(g97, "max_spindle_rpm", -1)),
            only("/max_spindle_rpm"));
  EXPECT_EQ(kGroovingCycleEndpoint.pointers(without(paper_groove(), "max_spindle_rpm")),
            only("/max_spindle_rpm"));
}

TEST(GroovingCycleEndpoint, ShiftAndToolWidthInsideTheGroove) {
  for (const double value : {0.0, -0.4, 10.4, 11.0}) {
    EXPECT_EQ(kGroovingCycleEndpoint.pointers(with(paper_groove(), "shift_mm", value)),
              only("/shift_mm"))
        << value;
    EXPECT_EQ(kGroovingCycleEndpoint.pointers(
                  with(without(paper_groove(), "shift_mm"), "tool_width_mm", value)),
              only("/tool_width_mm"))
        << value;
  }
}

TEST(GroovingCycleEndpoint, AnglesDwellClearanceAndRapidOutOfRange) {
  EXPECT_EQ(kGroovingCycleEndpoint.pointers(with(paper_groove(), "minor_edge_angle_deg", -0.1)),
            only("/minor_edge_angle_deg"));
  EXPECT_EQ(kGroovingCycleEndpoint.pointers(with(paper_groove(), "minor_edge_angle_deg", 90)),
            only("/minor_edge_angle_deg"));
  EXPECT_EQ(kGroovingCycleEndpoint.answer(with(paper_groove(), "minor_edge_angle_deg", 0)).status,
            200);
  EXPECT_EQ(kGroovingCycleEndpoint.pointers(with(paper_groove(), "dwell_revolutions", -1)),
            only("/dwell_revolutions"));
  EXPECT_EQ(kGroovingCycleEndpoint.answer(with(paper_groove(), "dwell_revolutions", 0)).status,
            200);
  for (const char* key : {"approach_clearance_mm", "rapid_mm_per_min"}) {
    EXPECT_EQ(kGroovingCycleEndpoint.pointers(with(paper_groove(), key, 0)),
              only(std::string("/") + key))
        << key;
    EXPECT_EQ(kGroovingCycleEndpoint.pointers(with(paper_groove(), key, -2)),
              only(std::string("/") + key))
        << key;
  }
}

TEST(GroovingCycleEndpoint, ImpossibleCombinationsPointAtTheWholeRequest) {
  // B + X2 != W; B <= X2; N > 20000; a word that prints as zero.
  const api::ApiResponse mismatch =
      kGroovingCycleEndpoint.answer(with(paper_groove(), "tool_width_mm", 9.9));
  EXPECT_EQ(kGroovingCycleEndpoint.pointers(with(paper_groove(), "tool_width_mm", 9.9)), only(""));
  EXPECT_NE(mismatch.body.find("tool_and_shift_mismatch"), std::string::npos) << mismatch.body;
  EXPECT_EQ(kGroovingCycleEndpoint.pointers(
                with(with(paper_groove(), "groove_width_mm", 1.0), "shift_mm", 0.5)),
            only(""));
  json deep = with(with(paper_groove(), "start_diameter_mm", 1000), "feed_per_rev_mm", 0.01);
  EXPECT_EQ(kGroovingCycleEndpoint.answer(with(deep, "groove_depth_mm", 200)).status, 200);
  const api::ApiResponse too_many =
      kGroovingCycleEndpoint.answer(with(deep, "groove_depth_mm", 200.01));
  EXPECT_EQ(kGroovingCycleEndpoint.pointers(with(deep, "groove_depth_mm", 200.01)), only(""));
  EXPECT_NE(too_many.body.find("20000"), std::string::npos) << too_many.body;
  EXPECT_EQ(kGroovingCycleEndpoint.pointers(with(paper_groove(), "dwell_revolutions", 1e-6)),
            only(""));
  EXPECT_EQ(kGroovingCycleEndpoint.pointers(
                with(with(paper_groove(), "feed_per_rev_mm", 0.00004), "groove_depth_mm", 0.4)),
            only(""));
}

TEST(GroovingCycleEndpoint, ProgramMembersOfALatheProgram) {
  // tool_number 1..99 (a turret), integer.
  for (const json& tool : {json(0), json(100), json(7.5), json("7")}) {
    EXPECT_EQ(
        kGroovingCycleEndpoint.pointers(with_program(paper_groove(), {{"tool_number", tool}})),
        only("/program/tool_number"))
        << tool;
  }
  EXPECT_EQ(kGroovingCycleEndpoint
                .answer(with_program(paper_groove(), {{"dialect", "fanuc"}, {"tool_number", 99}}))
                .status,
            200);
  // G58/G59 are no work offsets on Sinumerik; fine elsewhere.
  EXPECT_EQ(kGroovingCycleEndpoint.pointers(
                with_program(paper_groove(), {{"dialect", "sinumerik"}, {"work_offset", "G58"}})),
            only("/program/work_offset"));
  EXPECT_EQ(kGroovingCycleEndpoint.pointers(
                with_program(paper_groove(), {{"dialect", "sinumerik"}, {"work_offset", "G59"}})),
            only("/program/work_offset"));
  EXPECT_EQ(
      kGroovingCycleEndpoint
          .answer(with_program(paper_groove(), {{"dialect", "fanuc"}, {"work_offset", "G59"}}))
          .status,
      200);
  // program_number is Fanuc's.
  for (const char* dialect : {"linuxcnc", "sinumerik"}) {
    EXPECT_EQ(kGroovingCycleEndpoint.pointers(
                  with_program(paper_groove(), {{"dialect", dialect}, {"program_number", 12}})),
              only("/program/program_number"))
        << dialect;
  }
  EXPECT_EQ(
      kGroovingCycleEndpoint
          .answer(with_program(paper_groove(), {{"dialect", "fanuc"}, {"program_number", 12}}))
          .status,
      200);
  // The milling programs' members are unknown here.
  for (const char* key : {"tool_length_offset", "safe_z_mm", "clearance_mm",
                          "plunge_feed_mm_per_min", "rapid_mm_per_min"}) {
    const json value = std::string(key) == "tool_length_offset" ? json(true) : json(5);
    EXPECT_EQ(kGroovingCycleEndpoint.pointers(
                  with_program(paper_groove(), {{"tool_number", 3}, {key, value}})),
              only(std::string("/program/") + key))
        << key;
  }
}

TEST(GroovingCycleEndpoint, UnknownAndNonNumericMembersPointAtThemselves) {
  EXPECT_EQ(kGroovingCycleEndpoint.pointers(with(paper_groove(), "extra", 1)), only("/extra"));
  // The wide-groove scheme (Fig. 1b) is not part of the endpoint.
  EXPECT_EQ(kGroovingCycleEndpoint.pointers(with(paper_groove(), "swivel_angle_deg", 5)),
            only("/swivel_angle_deg"));
  EXPECT_EQ(kGroovingCycleEndpoint.pointers(with(paper_groove(), "shift_mm", "0.4")),
            only("/shift_mm"));
  EXPECT_EQ(kGroovingCycleEndpoint.pointers(with(paper_groove(), "dwell_revolutions", true)),
            only("/dwell_revolutions"));
  // Several at once: all listed.
  json broken = with(with(paper_groove(), "extra", 1), "groove_width_mm", 0);
  broken.erase("nose_radius_mm");
  EXPECT_EQ(kGroovingCycleEndpoint.pointers(broken),
            (std::set<std::string>{"/extra", "/groove_width_mm", "/nose_radius_mm"}));
}

TEST(GroovingCycleEndpoint, PlainTextAnswerIsTheProgramWithItsFileName) {
  struct Case {
    json program;
    const char* file_name;
  };
  for (const Case& c : {Case{json::object(), "CUTCALC.ngc"},
                        Case{{{"dialect", "fanuc"}, {"program_number", 12}}, "O0012.nc"},
                        Case{{{"dialect", "sinumerik"}, {"name", "GROOVE_1"}}, "GROOVE_1.MPF"},
                        Case{{{"name", "RING_2"}, {"units", "inch"}}, "RING_2.ngc"}}) {
    kGroovingCycleEndpoint.expect_program_download(with_program(paper_groove(), c.program),
                                                   c.file_name);
  }
}

TEST(GroovingCycleEndpoint, WarningsAreListedWithCodeAndDetailInOrder) {
  // Fanuc G97 n 150.5 over a 140 rpm limit, X2 0.6, N = 2.
  json request = without(paper_groove(), "cutting_speed_m_per_min");
  request["spindle_speed_rpm"] = 150.5;
  request["max_spindle_rpm"] = 140;
  request["shift_mm"] = 0.6;
  request["groove_depth_mm"] = 0.24;
  request["program"] = {{"dialect", "fanuc"}};
  const json body = parsed(kGroovingCycleEndpoint.answer(request));
  ASSERT_TRUE(body.contains("warnings")) << body.dump();
  std::vector<std::string> codes;
  for (const auto& warning : body.at("warnings")) {
    codes.push_back(warning.at("code").get<std::string>());
    EXPECT_FALSE(warning.at("detail").get<std::string>().empty());
  }
  EXPECT_EQ(codes, (std::vector<std::string>{"spindle_over_limit", "shift_outside_paper_range",
                                             "pattern_not_repeated", "spindle_speed_rounded"}));
}

}  // namespace
}  // namespace cutcalc::testing
