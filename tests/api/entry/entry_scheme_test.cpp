// POST /v1/entry-length with `include_scheme` over HTTP against the real server and through the
// handler pipeline: the opt-in scheme matches openapi.yaml, leaves the rest of the answer as it
// was, is absent unless asked for, rejects a non-boolean flag at its pointer and stays finite for
// extreme valid inputs.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "api/entry/entry_length_endpoint.h"
#include "support/project_contract.h"
#include "support/reference_compare.h"
#include "support/route_paths.h"
#include "support/sanity_checks.h"
#include "support/test_server.h"

namespace cutcalc::testing {
namespace {

using nlohmann::json;

json straight(double width, double angle = 90.0) {
  return {{"contour", "straight"}, {"width_mm", width}, {"angle_deg", angle}};
}

// Requests covering every contour kind on both sides, with and without an exit.
std::vector<json> sample_requests() {
  return {
      {{"cutter_diameter_mm", 50},
       {"entry", straight(25)},
       {"exit", straight(25)},
       {"length_mm", 80}},
      {{"cutter_diameter_mm", 30},
       {"offset_mm", -10},
       {"entry", straight(40, 60)},
       {"exit", straight(40, 120)},
       {"length_mm", 200}},
      {{"cutter_diameter_mm", 16},
       {"offset_mm", 20},
       {"entry", {{"contour", "convex_arc"}, {"radius_mm", 40}}}},
      {{"cutter_diameter_mm", 16},
       {"offset_mm", 4},
       {"entry", {{"contour", "concave_arc"}, {"radius_mm", 30}, {"width_mm", 40}}},
       {"exit", {{"contour", "wall"}, {"width_mm", 40}}},
       {"length_mm", 150}},
      {{"cutter_diameter_mm", 24},
       {"offset_mm", 7},
       {"entry", {{"contour", "convex_arc"}, {"radius_mm", 30}, {"width_mm", 50}}},
       {"exit", {{"contour", "concave_arc"}, {"radius_mm", 40}, {"width_mm", 50}}},
       {"length_mm", 150}},
  };
}

// A valid request and its answer both match openapi.yaml.
void expect_request_and_answer_conform(const json& request, const JsonReply& reply) {
  for (const auto& violation :
       test_support::project_contract().check_request("post", kEntryLengthPath, request)) {
    ADD_FAILURE() << "request: " << violation;
  }
  expect_conforms(kEntryLengthPath, reply);
}

std::vector<std::string> position_names(const json& side) {
  std::vector<std::string> names;
  for (const auto& position : side.at("positions")) {
    names.push_back(position.at("name").get<std::string>());
  }
  return names;
}

TEST(EntrySchemeApi, IncludeSchemeAddsASchemeThatMatchesTheContract) {
  for (json request : sample_requests()) {
    const JsonReply plain = post(kEntryLengthPath, request.dump());
    ASSERT_EQ(plain.status, 200) << plain.body;
    request["include_scheme"] = true;
    const JsonReply reply = post(kEntryLengthPath, request.dump());
    ASSERT_EQ(reply.status, 200) << reply.body;
    expect_request_and_answer_conform(request, reply);

    ASSERT_TRUE(reply.json.contains("scheme")) << reply.body;
    const json& scheme = reply.json["scheme"];
    EXPECT_NEAR(scheme.at("cutter_radius_mm").get<double>(),
                request["cutter_diameter_mm"].get<double>() / 2.0, 1e-12);
    EXPECT_EQ(position_names(scheme.at("entry")),
              (std::vector<std::string>{"start", "first_contact", "saturation"}));
    // The start is the answer's own start; first contact and saturation follow from it (E5-E7).
    const json& start = scheme["entry"]["positions"][0];
    EXPECT_EQ(start.at("x_mm"), reply.json["start"]["x_mm"]);
    EXPECT_EQ(start.at("y_mm"), reply.json["start"]["y_mm"]);
    EXPECT_NEAR(scheme["entry"]["positions"][1]["x_mm"].get<double>(),
                reply.json["start"]["x_mm"].get<double>() - request.value("approach_mm", 2.0),
                1e-9);
    EXPECT_NEAR(
        scheme["entry"]["positions"][2]["x_mm"].get<double>(),
        reply.json["start"]["x_mm"].get<double>() - reply.json["entry_length_mm"].get<double>(),
        1e-9);
    EXPECT_EQ(scheme.contains("exit"), request.contains("exit")) << reply.body;
    if (request.contains("exit")) {
      EXPECT_EQ(position_names(scheme["exit"]), std::vector<std::string>{"end"});
      EXPECT_EQ(scheme["exit"]["positions"][0]["x_mm"], reply.json["end"]["x_mm"]);
      EXPECT_EQ(scheme["exit"]["positions"][0]["y_mm"], reply.json["end"]["y_mm"]);
    }

    // Everything else is the answer without the scheme, unchanged.
    json rest = reply.json;
    rest.erase("scheme");
    EXPECT_EQ(rest, plain.json);
  }
}

TEST(EntrySchemeApi, ArcContoursAreSampledFinely) {
  json request = sample_requests()[2];  // convex arc entry
  request["include_scheme"] = true;
  const JsonReply reply = post(kEntryLengthPath, request.dump());
  ASSERT_EQ(reply.status, 200) << reply.body;
  const json& entry = reply.json["scheme"]["entry"];
  EXPECT_GE(entry["contour"].size(), 64U);
  EXPECT_EQ(entry["workpiece_outline"].size(), entry["contour"].size() + 2);
  // A full convex arc of R = 40 in the arc-axis frame: from (-40, -40) to (-40, 40) over the apex.
  EXPECT_NEAR(entry["contour"].front()["x_mm"].get<double>(), -40.0, 1e-9);
  EXPECT_NEAR(entry["contour"].front()["y_mm"].get<double>(), -40.0, 1e-9);
  EXPECT_NEAR(entry["contour"].back()["y_mm"].get<double>(), 40.0, 1e-9);
  EXPECT_NEAR(entry["strip"]["y_min_mm"].get<double>(), -40.0, 1e-12);
  EXPECT_NEAR(entry["strip"]["y_max_mm"].get<double>(), 40.0, 1e-12);
  // Band S = [K - r, K + r] = [12, 28] (E2), Y = y on an arc.
  EXPECT_NEAR(entry["band"]["y_min_mm"].get<double>(), 12.0, 1e-12);
  EXPECT_NEAR(entry["band"]["y_max_mm"].get<double>(), 28.0, 1e-12);
}

TEST(EntrySchemeApi, FalseOrAbsentLeavesTheAnswerByteForByte) {
  for (json request : sample_requests()) {
    const JsonReply absent = post(kEntryLengthPath, request.dump());
    request["include_scheme"] = false;
    const JsonReply off = post(kEntryLengthPath, request.dump());
    ASSERT_EQ(absent.status, 200) << absent.body;
    ASSERT_EQ(off.status, 200) << off.body;
    EXPECT_FALSE(off.json.contains("scheme")) << off.body;
    EXPECT_EQ(off.body, absent.body);
    expect_request_and_answer_conform(request, off);
  }
}

TEST(EntrySchemeApi, NonBooleanFlagIsAFieldError) {
  for (const json& flag :
       {json("true"), json(1), json(0), json(nullptr), json::array({true}), json::object()}) {
    json request = sample_requests()[0];
    request["include_scheme"] = flag;
    const JsonReply reply = post(kEntryLengthPath, request.dump());
    EXPECT_EQ(reply.status, 422) << flag.dump() << ": " << reply.body;
    EXPECT_TRUE(problem_names_pointer(reply.json, "/include_scheme"))
        << flag.dump() << ": " << reply.body;
    expect_conforms(kEntryLengthPath, reply);
  }
  // Listed beside the other field errors, not instead of them.
  json request = sample_requests()[0];
  request["include_scheme"] = "yes";
  request["cutter_diameter_mm"] = -1;
  const JsonReply reply = post(kEntryLengthPath, request.dump());
  EXPECT_EQ(reply.status, 422);
  EXPECT_TRUE(problem_names_pointer(reply.json, "/include_scheme")) << reply.body;
  EXPECT_TRUE(problem_names_pointer(reply.json, "/cutter_diameter_mm")) << reply.body;
}

TEST(EntrySchemeApi, ImpossibleInputIsStillTheModelsError) {
  // No contact: the scheme does not turn a 422 into anything else.
  json request = {{"cutter_diameter_mm", 10},
                  {"offset_mm", 40},
                  {"entry", straight(20)},
                  {"include_scheme", true}};
  const JsonReply reply = post(kEntryLengthPath, request.dump());
  EXPECT_EQ(reply.status, 422) << reply.body;
  EXPECT_TRUE(problem_names_pointer(reply.json, "")) << reply.body;
}

TEST(EntrySchemeApi, ExtremeValidInputsGiveFiniteSchemes) {
  const std::vector<json> extremes = {
      // nearly flat edges on the widest strips
      {{"cutter_diameter_mm", 1e-6}, {"entry", straight(1e6, 0.001)}},
      {{"cutter_diameter_mm", 1e6},
       {"entry", straight(1e6, 179.999)},
       {"exit", straight(1e6, 0.001)},
       {"length_mm", 1e6}},
      // huge and tiny arcs
      {{"cutter_diameter_mm", 1e-3},
       {"entry", {{"contour", "convex_arc"}, {"radius_mm", 1e6}}},
       {"exit", {{"contour", "convex_arc"}, {"radius_mm", 1e6}}},
       {"length_mm", 1e6}},
      {{"cutter_diameter_mm", 1e6},
       {"offset_mm", -4e5},
       {"entry", {{"contour", "concave_arc"}, {"radius_mm", 1e-6}, {"width_mm", 2e-6}}}},
      {{"cutter_diameter_mm", 2},
       {"offset_mm", 1e6},
       {"entry", {{"contour", "convex_arc"}, {"radius_mm", 1e6}}}},
  };
  for (json request : extremes) {
    request["include_scheme"] = true;
    if (expect_sane_answer(kEntryLengthPath, &api::entry::handle_entry_length, request) != 200) {
      ADD_FAILURE() << request.dump() << "\n" << post(kEntryLengthPath, request.dump()).body;
    }
  }
}

TEST(EntrySchemeApi, RandomExtremeRequestsWithSchemeAre200Or422WithFiniteNumbers) {
  std::mt19937_64 engine(20260704);
  static constexpr std::array<double, 12> kSpecial = {1e-6, 1e-3,    0.5,   1.0,      2.0, 45.0,
                                                      90.0, 179.999, 0.001, 999999.0, 1e6, -1e6};
  const auto any = [&engine] {
    switch (std::uniform_int_distribution<int>(0, 2)(engine)) {
      case 0:
        return kSpecial[std::uniform_int_distribution<std::size_t>(0, kSpecial.size() - 1)(engine)];
      case 1:
        return std::uniform_real_distribution<double>(-100.0, 100.0)(engine);
      default:
        return std::pow(10.0, std::uniform_real_distribution<double>(-6.0, 6.0)(engine));
    }
  };
  const auto coin = [&engine] { return std::uniform_int_distribution<int>(0, 1)(engine) == 1; };
  const auto contour = [&](bool exit, double width) {
    static constexpr std::array<const char*, 4> kKinds = {"straight", "convex_arc", "concave_arc",
                                                          "wall"};
    const std::string kind =
        kKinds[std::uniform_int_distribution<std::size_t>(0, exit ? 3 : 2)(engine)];
    json out = {{"contour", kind}, {"width_mm", width}};
    if (kind == "straight" && coin()) {
      out["angle_deg"] = any();
    }
    if (kind == "convex_arc" || kind == "concave_arc") {
      out["radius_mm"] = coin() ? width / 2.0 : any();
    }
    return out;
  };
  int answered = 0;
  for (int i = 0; i < 400 && !HasFailure(); ++i) {
    const double width = std::abs(any());
    json request = {
        {"cutter_diameter_mm", any()}, {"entry", contour(false, width)}, {"include_scheme", true}};
    if (coin()) {
      request["offset_mm"] = any();
    }
    if (coin()) {
      request["exit"] = contour(true, width);
      request["length_mm"] = any();
    }
    if (expect_sane_answer(kEntryLengthPath, &api::entry::handle_entry_length, request) == 200) {
      ++answered;
    }
  }
  EXPECT_GT(answered, 40) << "too few requests were answered to exercise the scheme";
}

}  // namespace
}  // namespace cutcalc::testing
