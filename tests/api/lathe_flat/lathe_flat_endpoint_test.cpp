// POST /v1/lathe-flat through its handler, no server (lathe-flat.md sections 2, 7 and 8): every
// row of the pointer table, the program members of a flat's program, the answer's members and the
// text/plain form with its file name.

#include "api/lathe_flat/lathe_flat_endpoint.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "api/json_endpoint.h"
#include "support/endpoint_probe.h"
#include "support/route_paths.h"

namespace cutcalc::testing {
namespace {

using nlohmann::json;

// Section 9: D32, t = 1, point tool, N = 10, f = 100 mm/min.
json paper_flat() {
  return {{"part_diameter_mm", 32}, {"flat_depth_mm", 1}, {"steps", 10}, {"feed_mm_per_min", 100}};
}

const EndpointProbe kLatheFlatEndpoint{kLatheFlatPath, &api::lathe_flat::handle_lathe_flat};

std::set<std::string> codes(const json& request) { return kLatheFlatEndpoint.codes(request); }

TEST(LatheFlatEndpoint, WorkedExampleAnswersWithEveryMemberOfSection8) {
  const api::ApiResponse response = kLatheFlatEndpoint.answer(paper_flat());
  ASSERT_EQ(response.status, 200) << response.body;
  const json body = parsed(response);
  for (const char* key : {"axis_distance_mm",
                          "flat_depth_mm",
                          "flat_width_mm",
                          "face_width_mm",
                          "across_flats_mm",
                          "engagement_half_angle_deg",
                          "sharp_corners",
                          "steps",
                          "layers",
                          "layer_depths_mm",
                          "x_travel_mm",
                          "steps_table",
                          "flatness_error_mm",
                          "flatness_error_estimate_mm",
                          "cut_blocks",
                          "shortest_block_mm",
                          "max_feed_by_block_rate_mm_per_min",
                          "cut_time_min",
                          "approach_time_min",
                          "machining_time_min",
                          "clear_x_mm",
                          "warnings",
                          "program",
                          "file_name",
                          "dialect",
                          "units",
                          "decimals"}) {
    EXPECT_TRUE(body.contains(key)) << key;
  }
  EXPECT_EQ(body.size(), 27U) << body.dump();
  EXPECT_FALSE(body.contains("steps_for_tolerance"));
  EXPECT_NEAR(body.at("engagement_half_angle_deg").get<double>(), 20.364135, 0.5e-6);
  EXPECT_NEAR(body.at("flatness_error_mm").get<double>(), 2.9531e-3, 0.5e-7);
  EXPECT_NEAR(body.at("machining_time_min").get<double>(), 0.121355, 0.5e-6);
  EXPECT_EQ(body.at("cut_blocks"), 20);
  EXPECT_EQ(body.at("layer_depths_mm"), json::array({1.0}));
  const json& table = body.at("steps_table");
  ASSERT_EQ(table.size(), 21U);
  for (const char* key : {"i", "c_deg", "x_mm", "dx_mm", "chord_mm"}) {
    EXPECT_TRUE(table.at(0).contains(key)) << key;
  }
  EXPECT_EQ(table.at(20).at("i"), 20);
  EXPECT_EQ(table.at(20).at("dx_mm"), 0.0);
  EXPECT_EQ(table.at(20).at("chord_mm"), 0.0);
  EXPECT_NEAR(table.at(0).at("dx_mm").get<double>(), 0.19844, 0.5e-5);
  EXPECT_EQ(body.at("warnings"), json::array());
  EXPECT_EQ(body.at("dialect"), "linuxcnc");
  EXPECT_EQ(body.at("units"), "mm");
  EXPECT_EQ(body.at("decimals"), 4);
  EXPECT_EQ(body.at("file_name"), "CUTCALC.ngc");
  const std::string program = body.at("program").get<std::string>();
  EXPECT_NE(program.find("\nG0 C20.3641\nG1 X32.0000 F100.0000\nG93\n"), std::string::npos);
}

TEST(LatheFlatEndpoint, DefaultsOfSection2) {
  // flats 1, R 0, a = t, t_b 2 ms, c 1 mm, z 0: explicit defaults give the same answer.
  json explicit_defaults = paper_flat();
  explicit_defaults["flats"] = 1;
  explicit_defaults["tool_radius_mm"] = 0;
  explicit_defaults["layer_depth_mm"] = 1;
  explicit_defaults["block_time_ms"] = 2;
  explicit_defaults["clearance_mm"] = 1;
  explicit_defaults["z_mm"] = 0;
  EXPECT_EQ(kLatheFlatEndpoint.answer(explicit_defaults).body,
            kLatheFlatEndpoint.answer(paper_flat()).body);
}

TEST(LatheFlatEndpoint, ATolerancePicksTheStepsAndIsReported) {
  const json by_tolerance = with(without(paper_flat(), "steps"), "flatness_tolerance_mm", 0.003);
  json body = parsed(kLatheFlatEndpoint.answer(by_tolerance));
  EXPECT_EQ(body.at("steps"), 10);
  EXPECT_EQ(body.at("steps_for_tolerance"), 10);
  body = parsed(kLatheFlatEndpoint.answer(with(by_tolerance, "steps", 4)));
  EXPECT_EQ(body.at("steps"), 4);
  EXPECT_EQ(body.at("steps_for_tolerance"), 10);
  ASSERT_EQ(body.at("warnings").size(), 1U);
  EXPECT_EQ(body.at("warnings").at(0).at("code"), "flatness_over_tolerance");
  EXPECT_FALSE(body.at("warnings").at(0).at("detail").get<std::string>().empty());
}

TEST(LatheFlatEndpoint, PositiveMembersZeroNegativeOrNotNumbersPointAtThemselves) {
  for (const char* key : {"part_diameter_mm", "feed_mm_per_min", "block_time_ms", "clearance_mm",
                          "layer_depth_mm", "flat_depth_mm"}) {
    const std::string pointer = std::string("/") + key;
    EXPECT_EQ(kLatheFlatEndpoint.pointers(with(paper_flat(), key, 0)), only(pointer)) << key;
    EXPECT_EQ(kLatheFlatEndpoint.pointers(with(paper_flat(), key, -1)), only(pointer)) << key;
    EXPECT_EQ(kLatheFlatEndpoint.pointers(with(paper_flat(), key, "1")), only(pointer)) << key;
    EXPECT_EQ(kLatheFlatEndpoint.pointers(with(paper_flat(), key, nullptr)), only(pointer)) << key;
  }
  const json no_depth = without(paper_flat(), "flat_depth_mm");
  for (const char* key : {"flat_width_mm", "axis_distance_mm"}) {
    EXPECT_EQ(kLatheFlatEndpoint.pointers(with(no_depth, key, 0)), only(std::string("/") + key))
        << key;
    EXPECT_EQ(kLatheFlatEndpoint.pointers(with(no_depth, key, -2)), only(std::string("/") + key))
        << key;
  }
  const json two_flats = with(no_depth, "flats", 2);
  EXPECT_EQ(kLatheFlatEndpoint.pointers(with(two_flats, "across_flats_mm", 0)),
            only("/across_flats_mm"));
  // R >= 0: zero is a point tool.
  EXPECT_EQ(kLatheFlatEndpoint.pointers(with(paper_flat(), "tool_radius_mm", -0.1)),
            only("/tool_radius_mm"));
  EXPECT_EQ(kLatheFlatEndpoint.answer(with(paper_flat(), "tool_radius_mm", 0)).status, 200);
  // z: any finite number.
  EXPECT_EQ(kLatheFlatEndpoint.answer(with(paper_flat(), "z_mm", -12.5)).status, 200);
  EXPECT_EQ(kLatheFlatEndpoint.pointers(with(paper_flat(), "z_mm", "0")), only("/z_mm"));
}

TEST(LatheFlatEndpoint, RequiredMembersPointAtThemselves) {
  EXPECT_EQ(kLatheFlatEndpoint.pointers(without(paper_flat(), "part_diameter_mm")),
            only("/part_diameter_mm"));
  EXPECT_EQ(kLatheFlatEndpoint.pointers(without(paper_flat(), "feed_mm_per_min")),
            only("/feed_mm_per_min"));
}

TEST(LatheFlatEndpoint, ExactlyOneOfDepthWidthAxisDistanceAndAcrossFlats) {
  EXPECT_EQ(kLatheFlatEndpoint.pointers(without(paper_flat(), "flat_depth_mm")), only(""));
  EXPECT_EQ(codes(without(paper_flat(), "flat_depth_mm")),
            std::set<std::string>{"exactly_one_field"});
  EXPECT_EQ(kLatheFlatEndpoint.pointers(with(paper_flat(), "flat_width_mm", 11)), only(""));
  EXPECT_EQ(kLatheFlatEndpoint.pointers(with(paper_flat(), "axis_distance_mm", 15)), only(""));
  EXPECT_EQ(
      kLatheFlatEndpoint.pointers(with(with(paper_flat(), "flats", 2), "across_flats_mm", 30)),
      only(""));
  const json no_depth = without(paper_flat(), "flat_depth_mm");
  EXPECT_EQ(kLatheFlatEndpoint.answer(with(no_depth, "flat_width_mm", 11)).status, 200);
  EXPECT_EQ(kLatheFlatEndpoint.answer(with(no_depth, "axis_distance_mm", 15)).status, 200);
  EXPECT_EQ(
      kLatheFlatEndpoint.answer(with(with(no_depth, "flats", 2), "across_flats_mm", 30)).status,
      200);
}

TEST(LatheFlatEndpoint, AcrossFlatsNeedsSeveralFlats) {
  const json by_size = with(without(paper_flat(), "flat_depth_mm"), "across_flats_mm", 30);
  EXPECT_EQ(kLatheFlatEndpoint.pointers(by_size), only("/across_flats_mm"));
  EXPECT_EQ(codes(by_size), std::set<std::string>{"needs_several_flats"});
  EXPECT_EQ(kLatheFlatEndpoint.pointers(with(by_size, "flats", 1)), only("/across_flats_mm"));
  EXPECT_EQ(kLatheFlatEndpoint.answer(with(by_size, "flats", 3)).status, 200);
}

TEST(LatheFlatEndpoint, FlatsAndStepsAreIntegersInRange) {
  for (const json& flats : {json(0), json(2.5), json(13), json("2"), json(-1)}) {
    EXPECT_EQ(kLatheFlatEndpoint.pointers(with(paper_flat(), "flats", flats)), only("/flats"))
        << flats;
  }
  for (const json& flats : {json(1), json(12), json(2.0)}) {
    EXPECT_EQ(kLatheFlatEndpoint.answer(with(paper_flat(), "flats", flats)).status, 200) << flats;
  }
  for (const json& steps : {json(0), json(1001), json(2.5), json("10"), json(true)}) {
    EXPECT_EQ(kLatheFlatEndpoint.pointers(with(paper_flat(), "steps", steps)), only("/steps"))
        << steps;
  }
  for (const json& steps : {json(1), json(1000)}) {
    EXPECT_EQ(kLatheFlatEndpoint.answer(with(paper_flat(), "steps", steps)).status, 200) << steps;
  }
}

TEST(LatheFlatEndpoint, ToleranceBounds) {
  const json by_tolerance = without(paper_flat(), "steps");
  for (const json& tolerance : {json(0), json(0.99e-6), json(1.01), json(-0.001), json("0.01")}) {
    EXPECT_EQ(kLatheFlatEndpoint.pointers(with(by_tolerance, "flatness_tolerance_mm", tolerance)),
              only("/flatness_tolerance_mm"))
        << tolerance;
  }
  EXPECT_EQ(kLatheFlatEndpoint.answer(with(by_tolerance, "flatness_tolerance_mm", 1)).status, 200);
  EXPECT_EQ(kLatheFlatEndpoint.answer(with(by_tolerance, "flatness_tolerance_mm", 1e-6)).status,
            200);
}

TEST(LatheFlatEndpoint, NeitherStepsNorToleranceIsRefusedAtTheWholeRequest) {
  EXPECT_EQ(kLatheFlatEndpoint.pointers(without(paper_flat(), "steps")), only(""));
  EXPECT_EQ(codes(without(paper_flat(), "steps")), std::set<std::string>{"at_least_one_field"});
}

TEST(LatheFlatEndpoint, AFlatOutsideThePartPointsAtTheGivenField) {
  const json no_depth = without(paper_flat(), "flat_depth_mm");
  struct Case {
    json request;
    const char* pointer;
  };
  for (const Case& c :
       {Case{with(paper_flat(), "flat_depth_mm", 16), "/flat_depth_mm"},
        Case{with(paper_flat(), "flat_depth_mm", 20), "/flat_depth_mm"},
        Case{with(no_depth, "axis_distance_mm", 16), "/axis_distance_mm"},
        Case{with(no_depth, "flat_width_mm", 32), "/flat_width_mm"},
        Case{with(with(no_depth, "flats", 4), "across_flats_mm", 32), "/across_flats_mm"}}) {
    EXPECT_EQ(kLatheFlatEndpoint.pointers(c.request), only(c.pointer)) << c.request;
    EXPECT_EQ(codes(c.request), std::set<std::string>{"flat_outside_part"}) << c.request;
  }
  EXPECT_EQ(kLatheFlatEndpoint.answer(with(paper_flat(), "flat_depth_mm", 15.99)).status, 200);
  EXPECT_EQ(kLatheFlatEndpoint.answer(with(no_depth, "flat_width_mm", 31.99)).status, 200);
}

TEST(LatheFlatEndpoint, AnUnmetTolerancePointsAtTheTolerance) {
  const json deep = {{"part_diameter_mm", 1000},
                     {"flat_depth_mm", 400},
                     {"tool_radius_mm", 20},
                     {"flatness_tolerance_mm", 1e-6},
                     {"feed_mm_per_min", 100}};
  EXPECT_EQ(kLatheFlatEndpoint.pointers(deep), only("/flatness_tolerance_mm"));
  EXPECT_EQ(codes(deep), std::set<std::string>{"tolerance_unmet"});
}

TEST(LatheFlatEndpoint, TooManyBlocksAndAFeedPrintingAsZeroPointAtTheWholeRequest) {
  // 2 N m L = 2 x 1000 x 10 x 11 = 220 000 > 200 000.
  json many = with(with(paper_flat(), "steps", 1000), "flats", 10);
  EXPECT_EQ(kLatheFlatEndpoint.answer(with(many, "layer_depth_mm", 0.1)).status, 200);
  many["layer_depth_mm"] = 0.0999;
  EXPECT_EQ(kLatheFlatEndpoint.pointers(many), only(""));
  EXPECT_EQ(codes(many), std::set<std::string>{"too_many_cut_blocks"});
  EXPECT_NE(kLatheFlatEndpoint.answer(many).body.find("200000"), std::string::npos)
      << kLatheFlatEndpoint.answer(many).body;
  const json slow = {
      {"part_diameter_mm", 1000}, {"flat_depth_mm", 400}, {"steps", 1}, {"feed_mm_per_min", 0.001}};
  EXPECT_EQ(kLatheFlatEndpoint.pointers(slow), only(""));
  EXPECT_EQ(codes(slow), std::set<std::string>{"word_prints_as_zero"});
}

TEST(LatheFlatEndpoint, FanucIsRefusedAtTheDialect) {
  const json fanuc = with_program(paper_flat(), {{"dialect", "fanuc"}});
  EXPECT_EQ(kLatheFlatEndpoint.pointers(fanuc), only("/program/dialect"));
  EXPECT_EQ(codes(fanuc), std::set<std::string>{"dialect_unsupported"});
  EXPECT_EQ(kLatheFlatEndpoint.pointers(with_program(paper_flat(), {{"dialect", "heidenhain"}})),
            only("/program/dialect"));
  EXPECT_EQ(
      kLatheFlatEndpoint.answer(with_program(paper_flat(), {{"dialect", "sinumerik"}})).status,
      200);
}

TEST(LatheFlatEndpoint, ProgramMembersOfAFlatProgram) {
  // dialect, units, decimals (3..6), name, program_number (fanuc only): as programs.md.
  for (const json& decimals : {json(2), json(7), json(4.5)}) {
    EXPECT_EQ(kLatheFlatEndpoint.pointers(with_program(paper_flat(), {{"decimals", decimals}})),
              only("/program/decimals"))
        << decimals;
  }
  EXPECT_EQ(
      kLatheFlatEndpoint.answer(with_program(paper_flat(), {{"decimals", 6}, {"units", "inch"}}))
          .status,
      200);
  EXPECT_EQ(kLatheFlatEndpoint.pointers(with_program(paper_flat(), {{"units", "cm"}})),
            only("/program/units"));
  EXPECT_EQ(kLatheFlatEndpoint.pointers(with_program(paper_flat(), {{"program_number", 12}})),
            only("/program/program_number"));
  EXPECT_EQ(kLatheFlatEndpoint.pointers(with_program(paper_flat(), {{"name", "bad name!"}})),
            only("/program/name"));
  // The tool, work offset, coolant and milling members are not the flat's: unknown.
  for (const char* key : {"tool_number", "work_offset", "coolant", "tool_length_offset",
                          "safe_z_mm", "clearance_mm", "rapid_mm_per_min"}) {
    const json value = std::string(key) == "work_offset"          ? json("G55")
                       : std::string(key) == "coolant"            ? json("flood")
                       : std::string(key) == "tool_length_offset" ? json(true)
                                                                  : json(3);
    EXPECT_EQ(kLatheFlatEndpoint.pointers(with_program(paper_flat(), {{key, value}})),
              only(std::string("/program/") + key))
        << key;
  }
}

TEST(LatheFlatEndpoint, UnknownMembersPointAtThemselvesAndAllErrorsAreListed) {
  EXPECT_EQ(kLatheFlatEndpoint.pointers(with(paper_flat(), "feed_mm_min", 100)),
            only("/feed_mm_min"));
  json broken = with(with(paper_flat(), "extra", 1), "part_diameter_mm", 0);
  broken.erase("feed_mm_per_min");
  broken.erase("steps");
  EXPECT_EQ(kLatheFlatEndpoint.pointers(broken),
            (std::set<std::string>{"", "/extra", "/part_diameter_mm", "/feed_mm_per_min"}));
}

TEST(LatheFlatEndpoint, PlainTextAnswerIsTheProgramWithItsFileName) {
  struct Case {
    json program;
    const char* file_name;
  };
  for (const Case& c : {Case{json::object(), "CUTCALC.ngc"},
                        Case{{{"dialect", "sinumerik"}, {"name", "FLAT_1"}}, "FLAT_1.MPF"},
                        Case{{{"name", "HEX_2"}, {"units", "inch"}}, "HEX_2.ngc"}}) {
    kLatheFlatEndpoint.expect_program_download(with_program(paper_flat(), c.program), c.file_name);
  }
}

TEST(LatheFlatEndpoint, WarningsAreListedWithCodeAndDetailInOrder) {
  json request = with(paper_flat(), "feed_mm_per_min", 20000);
  request["flatness_tolerance_mm"] = 0.002;
  const json body = parsed(kLatheFlatEndpoint.answer(request));
  ASSERT_TRUE(body.contains("warnings")) << body.dump();
  std::vector<std::string> found;
  for (const auto& warning : body.at("warnings")) {
    found.push_back(warning.at("code").get<std::string>());
    EXPECT_FALSE(warning.at("detail").get<std::string>().empty());
  }
  EXPECT_EQ(found,
            (std::vector<std::string>{"feed_exceeds_block_rate", "flatness_over_tolerance"}));
}

}  // namespace
}  // namespace cutcalc::testing
