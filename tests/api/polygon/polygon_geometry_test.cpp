// /v1/polygon-hole/gcode with `include_geometry`: the drawing geometry in the JSON answer only,
// the rest of the answer and the plain-text program unchanged, field errors at
// /include_geometry, and every answer within openapi.yaml.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

#include "api/polygon/polygon_hole_endpoint.h"
#include "support/project_contract.h"
#include "support/reference_compare.h"
#include "support/route_paths.h"
#include "support/sanity_checks.h"
#include "support/test_server.h"

namespace cutcalc::testing {
namespace {

using nlohmann::json;

// The paper's square a = 16 (square_a16_g95), one layer.
json square(int faces = 4, double d = 16.0) {
  return {{"faces", faces},
          {"inscribed_diameter_mm", d},
          {"depth_mm", 0.1},
          {"step_down_mm", 0.1},
          {"spindle_speed_rpm", 30}};
}

json with_geometry(json request, const json& flag = true) {
  request["include_geometry"] = flag;
  return request;
}

std::string plain_program(const json& request) {
  auto client = TestServer::shared().client();
  const auto reply = client->Post(kPolygonGcodePath, {{"Accept", "text/plain"}}, request.dump(),
                                  "application/json");
  EXPECT_TRUE(reply);
  if (!reply) {
    return {};
  }
  EXPECT_EQ(reply->status, 200);
  EXPECT_EQ(reply->get_header_value("Content-Type"), "text/plain; charset=us-ascii");
  return reply->body;
}

std::size_t point_count(const json& geometry) {
  std::size_t total = geometry.at("polygon").size() + geometry.at("centre_path").size() +
                      geometry.at("predicted_hole").size();
  for (const json& pose : geometry.at("rotor_positions")) {
    total += pose.at("outline").size() + 1;
  }
  return total;
}

TEST(PolygonGeometryApi, GeometryComesOnlyWhenAskedAndChangesNothingElse) {
  for (const bool c_axis : {false, true}) {
    json request = square();
    if (c_axis) {
      request["synchronization"] = "c_axis";
    }
    const JsonReply plain = post_ok(kPolygonGcodePath, request);
    EXPECT_FALSE(plain.json.contains("geometry"));
    const JsonReply off = post_ok(kPolygonGcodePath, with_geometry(request, false));
    EXPECT_EQ(off.body, plain.body);  // false is the default, byte for byte
    JsonReply on = post_ok(kPolygonGcodePath, with_geometry(request));
    ASSERT_TRUE(on.json.contains("geometry"));
    on.json.erase("geometry");
    EXPECT_EQ(on.json, plain.json);
  }
}

TEST(PolygonGeometryApi, PlainTextProgramIsUnchanged) {
  const std::string without = plain_program(square());
  const std::string with = plain_program(with_geometry(square()));
  EXPECT_FALSE(without.empty());
  EXPECT_EQ(with, without);
  EXPECT_EQ(with.find("geometry"), std::string::npos);
}

TEST(PolygonGeometryApi, GeometryOfThePaperSquare) {
  const JsonReply reply = post_ok(kPolygonGcodePath, with_geometry(square()));
  const json& g = reply.json.at("geometry");
  // P1: a = 16, R_c = 8 sqrt 2; V_0 at the bottom right.
  ASSERT_EQ(g.at("polygon").size(), 4u);
  EXPECT_NEAR(g.at("polygon")[0].at("x_mm").get<double>(), 8.0, 1e-12);
  EXPECT_NEAR(g.at("polygon")[0].at("y_mm").get<double>(), -8.0, 1e-12);
  EXPECT_EQ(g.at("corner").at("vertex"), g.at("polygon")[0]);
  // Section 3: the centre path starts at (0, e), e = eccentricity_mm.
  EXPECT_NEAR(g.at("centre_path")[0].at("y_mm").get<double>(),
              reply.json.at("eccentricity_mm").get<double>(), 1e-12);
  // P15: the predicted hole keeps corner_gap_mm from the vertex, up to its sampling.
  const double gap = reply.json.at("corner_gap_mm").get<double>();
  double nearest = 1e9;
  for (const json& p : g.at("predicted_hole")) {
    nearest = std::min(
        nearest, std::hypot(p.at("x_mm").get<double>() - 8.0, p.at("y_mm").get<double>() + 8.0));
  }
  EXPECT_GE(nearest, gap - 1e-9);
  EXPECT_LE(nearest, gap * 1.01);
  const double view = g.at("corner").at("view_radius_mm").get<double>();
  EXPECT_GT(view, 2.0 * gap);
  EXPECT_LT(view, 16.0);
  // The rotor poses stay inside the square (P26's penetration <= 0 on the exact motion).
  for (const json& pose : g.at("rotor_positions")) {
    for (const json& p : pose.at("outline")) {
      EXPECT_LE(std::abs(p.at("x_mm").get<double>()), 8.0 + 1e-9);
      EXPECT_LE(std::abs(p.at("y_mm").get<double>()), 8.0 + 1e-9);
    }
  }
}

TEST(PolygonGeometryApi, EveryFaceCountAnswersWithinTheContractAndBounds) {
  for (int faces = 3; faces <= 12; ++faces) {
    SCOPED_TRACE(::testing::Message() << faces << " faces");
    const JsonReply reply = post_ok(kPolygonGcodePath, with_geometry(square(faces, 20.0)));
    const json& g = reply.json.at("geometry");
    EXPECT_EQ(g.at("polygon").size(), static_cast<std::size_t>(faces));
    EXPECT_GE(g.at("rotor_positions").size(), 3u);
    EXPECT_LE(point_count(g), 3000u);
  }
  // The smallest and largest holes: finite, no negative length, within the contract.
  for (const int faces : {3, 12}) {
    for (const double d : {1.0, 1e6}) {
      json request = with_geometry(square(faces, d));
      request["tolerance_mm"] = 0.1;
      EXPECT_EQ(expect_sane_answer(kPolygonGcodePath, &api::polygon::handle_polygon_hole, request),
                200)
          << faces << " faces, d " << d;
    }
  }
}

TEST(PolygonGeometryApi, WrongTypeNamesTheField) {
  for (const json& bad : {json(1), json(0), json("true"), json(nullptr), json::array()}) {
    SCOPED_TRACE(bad.dump());
    const JsonReply reply = post(kPolygonGcodePath, with_geometry(square(), bad).dump());
    EXPECT_EQ(reply.status, 422) << reply.body;
    EXPECT_TRUE(problem_names_pointer(reply.json, "/include_geometry")) << reply.body;
    EXPECT_EQ(expect_sane_answer(kPolygonGcodePath, &api::polygon::handle_polygon_hole,
                                 with_geometry(square(), bad)),
              422);
    const auto v = test_support::project_contract().check_request("POST", kPolygonGcodePath,
                                                                  with_geometry(square(), bad));
    EXPECT_TRUE(std::any_of(v.begin(), v.end(), [](const std::string& violation) {
      return violation.rfind("at \"/include_geometry\"", 0) == 0;
    }));
  }
  EXPECT_TRUE(test_support::project_contract()
                  .check_request("POST", kPolygonGcodePath, with_geometry(square()))
                  .empty());
  // Model errors are unchanged by the flag: a program of more than 200 000 arc blocks.
  json too_large = with_geometry(square());
  too_large["depth_mm"] = 1000;
  too_large["step_down_mm"] = 0.001;
  const JsonReply reply = post(kPolygonGcodePath, too_large.dump());
  EXPECT_EQ(reply.status, 422);
  EXPECT_TRUE(problem_names_pointer(reply.json, "/step_down_mm")) << reply.body;
}

}  // namespace
}  // namespace cutcalc::testing
