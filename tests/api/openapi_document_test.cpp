// openapi.yaml is the formal contract: these tests check that the document is complete and
// self-consistent (its examples satisfy its own schemas, every operation documents its errors),
// that the reference cases satisfy it, and that the contract checker used by the API tests can
// fail.

#include <cmath>
#include <fstream>
#include <iomanip>
#include <map>
#include <numbers>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "api/grooving/grooving_cycle_endpoint.h"
#include "api/lathe_flat/lathe_flat_endpoint.h"
#include "support/endpoint_probe.h"
#include "support/project_contract.h"
#include "support/route_paths.h"

#ifndef CUTCALC_OPENAPI_PATH
#error "CUTCALC_OPENAPI_PATH (path to openapi.yaml, a string literal) must be defined"
#endif

namespace {

using cutcalc::test_support::OpenApiContract;
using cutcalc::test_support::project_contract;
using cutcalc::testing::EndpointProbe;
using nlohmann::json;

const json& doc() {
  static const json d = project_contract().document();
  return d;
}

std::string join(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines) {
    out += "\n  " + l;
  }
  return out;
}

// True if one violation names this JSON Pointer (violations quote the pointer they are about).
bool names_pointer(const std::vector<std::string>& violations, const std::string& pointer) {
  for (const auto& v : violations) {
    if (v.find("\"" + pointer + "\"") != std::string::npos) {
      return true;
    }
  }
  return false;
}

const json& deref(const json& obj) {
  const json* cur = &obj;
  while (cur->is_object() && cur->contains("$ref")) {
    cur = &doc().at(json::json_pointer((*cur)["$ref"].get<std::string>().substr(1)));
  }
  return *cur;
}

const std::set<std::string> kMethods = {"get",     "put",  "post",  "delete",
                                        "options", "head", "patch", "trace"};

struct Operation {
  std::string method;  // upper case
  std::string path;
  const json* op;
};

std::vector<Operation> operations() {
  std::vector<Operation> ops;
  for (const auto& [path, item] : doc()["paths"].items()) {
    for (const auto& [method, op] : item.items()) {
      if (kMethods.count(method) == 0) {
        continue;
      }
      std::string upper = method;
      for (auto& c : upper) {
        c = static_cast<char>(c - 'a' + 'A');
      }
      ops.push_back({upper, path, &op});
    }
  }
  return ops;
}

// (name, value) of every example of a media type object.
std::vector<std::pair<std::string, json>> examples_of(const json& media) {
  std::vector<std::pair<std::string, json>> out;
  if (media.contains("example")) {
    out.emplace_back("example", media["example"]);
  }
  if (media.contains("examples")) {
    for (const auto& [name, ex] : media["examples"].items()) {
      const json& e = deref(ex);
      if (e.contains("value")) {
        out.emplace_back(name, e["value"]);
      }
    }
  }
  return out;
}

// A complete, valid entry-length response (reference case P03).
json entry_length_body() {
  return json::parse(R"({
    "engagement_length_mm": 3.3493649054, "entry_length_mm": 5.3493649054,
    "start": {"x_mm": 27.0, "y_mm": 12.5}, "steady_width_mm": 25.0,
    "end": {"x_mm": 21.6506350946, "y_mm": 12.5}, "working_stroke_mm": 87.3493649054})");
}

json main_time_request() {
  return json::parse(R"({
    "cutter_diameter_mm": 50, "teeth": 4, "spindle_speed_rpm": 1000, "feed_per_tooth_mm": 0.1,
    "entry_feed_factor": 0.5, "length_mm": 120,
    "entry": {"contour": "straight", "width_mm": 80, "angle_deg": 90},
    "exit": {"contour": "straight", "width_mm": 80, "angle_deg": 90},
    "allowance": {"width_mm": 80, "width_of_cut_mm": 45, "depth_mm": 5, "depth_of_cut_mm": 2}})");
}

// Reference case rs-sample-up: the paper's flat, given by its depth.
json resultant_speeds_request() {
  return json::parse(R"({"tool_radius_mm": 10.0, "workpiece_radius_mm": 16.0, "flat_depth_mm": 1.0,
    "tool_speed_rpm": 3000, "workpiece_speed_rpm": 10, "tool_feed_mm_per_min": 100,
    "milling": "up"})");
}

// Reference case rs-sample-up-feed-toward-axis-middle: one complete contact point.
json resultant_speeds_body() {
  return json::parse(R"({"engagement_half_angle_deg": 20.281649812950175, "points": [{
    "contact_angle_deg": 0, "contact_radius_mm": 15.0, "contact_polar_angle_deg": 0.0,
    "tool_speed_m_per_min": 188.4955592153876, "workpiece_speed_m_per_min": 0.9424777960769379,
    "resultant_feed_mm_per_min": 947.7681130413928, "resultant_speed_m_per_min": 189.43806340531728,
    "resultant_angle_deg": -0.030245126636163414, "sense": "up", "kinematic_ratio": 0.005,
    "normal_speed_m_per_min": 189.43806340531728, "along_edge_speed_m_per_min": 0.0}]})");
}

// Reference case gw-target-paper-13.2 (the spec's worked example R.5 with a target).
json groove_wall_request() {
  return json::parse(
      R"({"feed_mm": 0.12, "nose_radius_mm": 0.3, "minor_edge_angle_deg": 2, "target_rz_um": 13.2})");
}

// Reference case bm-table1-S0.2.
json bore_milling_request() {
  return json::parse(R"({"bore_radius_mm": 81.0, "cutter_radius_mm": 32.4, "teeth": 4,
    "feed_per_rev_mm": 0.2, "milling": "up"})");
}

// Reference case square_a16_g95: the paper's square a = 16 mm, defaults otherwise.
json polygon_hole_request() {
  return json::parse(R"({"faces": 4, "inscribed_diameter_mm": 16.0, "depth_mm": 0.2,
    "step_down_mm": 0.1, "spindle_speed_rpm": 30})");
}

// The program header of spec polygon-holes.md section 5 for N faces and inscribed diameter d.
std::string polygon_program_header(int faces, double d) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(4) << "%\n(CUTCALC POLYGON HOLE N" << faces << " D" << d
      << " A" << d * std::tan(std::numbers::pi / faces) << ")\n";
  return out.str();
}

// A short program with the header and the end that section 5 prescribes.
std::string polygon_program(int faces, double d) {
  return polygon_program_header(faces, d) +
         "G21 G17 G90 G40 G80 G94\nG0 Z5.0000\nS30.0000 M3\nG0 X0.0000 Y1.2376\n"
         "G95 F24.0265\nG1 Z0.0000\nG3 X-0.2709 Y1.2200 Z-0.0034 I0.0000 J-2.0974\n"
         "G0 Z5.0000\nG94\nM5\nM30\n%\n";
}

// The rotor, corner radius and times of the square a = 16 at 30 rpm in 2 layers (spec
// polygon-holes.md section 13's worked figures), members every polygon-hole answer has.
json polygon_rotor_and_times() {
  return json::parse(R"({"rotor": {"corners": 3, "corner_circle_diameter_mm": 18.4752,
    "corner_angle_deg": 120.0, "width_min_mm": 16.0, "width_max_mm": 16.0,
    "neck_diameter_max_mm": 13.5248, "flank_arcs": [
      {"radius_mm": 16.0, "centre": {"x_mm": -8.0, "y_mm": 4.6188}, "start_angle_deg": -60.0,
       "end_angle_deg": -30.0},
      {"radius_mm": 16.0, "centre": {"x_mm": -8.0, "y_mm": 4.6188}, "start_angle_deg": -30.0,
       "end_angle_deg": 0.0}]},
    "corner_radius_mm": 1.5692, "working_time_min": 0.066667, "plunge_time_min": 0.0069368,
    "rapid_time_min": 0.00052, "cycle_time_min": 0.0741238})");
}

// A complete answer to polygon_hole_request() (reference case square_a16_g95 and its info).
json polygon_hole_body() {
  json body = json::parse(R"({"blocks_per_loop": 25, "loop_length_mm": 8.00822093506,
    "feed_per_rev_mm": 24.0246628052, "eccentricity_mm": 1.23760430703,
    "max_path_deviation_mm": 0.000505685, "predicted_overcut_mm": 0.0414403,
    "uncut_corner_area_mm2": 3.14869997153, "corner_gap_mm": 0.771010537418,
    "max_feed_by_block_rate_mm_per_min": 6880.93938,
    "warnings": [{"code": "phase_not_locked", "detail": "G95 does not lock the phase",
                  "message": "G95 does not lock the rotor angle to the path"}]})");
  body["program"] = polygon_program(4, 16.0);
  body.update(polygon_rotor_and_times());
  return body;
}

// polygon-hole.json states in expect.body only the numbers it expects exactly; the quality
// figures are bounds (expect.max, expect.min), the warnings a set of codes, and the program is
// checked by rules of its own. This assembles the complete answer such a case describes: each
// bounded figure at its bound (the middle of a min..max band), one warning per code, a program
// with the prescribed header. The contract must accept it, so every field name and warning code
// of the reference file must be documented.
json complete_polygon_body(const json& reference_case) {
  const json& request = reference_case["request"];
  const json& expect = reference_case["expect"];
  json body = expect["body"];
  const json max = expect.value("max", json::object());
  const json min = expect.value("min", json::object());
  for (const auto& [key, bound] : max.items()) {
    body[key] =
        min.contains(key) ? json(0.5 * (bound.get<double>() + min[key].get<double>())) : bound;
  }
  for (const auto& [key, bound] : min.items()) {
    if (!body.contains(key)) {
      body[key] = bound;
    }
  }
  body["warnings"] = json::array();
  for (const auto& code : expect["warning_codes"]) {
    body["warnings"].push_back(
        {{"code", code}, {"detail", "as in the reference case"}, {"message", "a sentence"}});
  }
  body["program"] =
      polygon_program(request["faces"].get<int>(), request["inscribed_diameter_mm"].get<double>());
  const json rotor_and_times = polygon_rotor_and_times();
  for (const auto& [key, value] : rotor_and_times.items()) {
    if (!body.contains(key)) {
      body[key] = value;  // the older file states no rotor or time
    }
  }
  return body;
}

json problem(const std::string& type, const std::string& title, int status,
             json errors = json::array()) {
  return json{{"type", type},
              {"title", title},
              {"status", status},
              {"detail", "x"},
              {"instance", "/v1/main-time"},
              {"request_id", "abc-1"},
              {"errors", std::move(errors)}};
}

// ------------------------------------------------------------------------------------------------

TEST(OpenApiDocument, LoadsAsOpenApi31WithInfoAndServers) {
  ASSERT_NO_THROW(project_contract());
  EXPECT_EQ(doc()["openapi"], "3.1.0");
  EXPECT_EQ(doc()["info"]["title"], "cutcalc");
  EXPECT_EQ(doc()["info"]["version"], "0.1.0");
  EXPECT_EQ(doc()["info"]["license"]["name"], "MIT");
  EXPECT_EQ(doc()["servers"][0]["url"], "http://127.0.0.1:8080");
  // The calculation paths are the route table's (tests/api/route_table_test.cpp checks both ways).
  for (const char* path : {"/healthz", "/readyz", "/version", "/metrics", "/openapi.yaml"}) {
    EXPECT_TRUE(doc()["paths"].contains(path)) << path;
  }
}

TEST(OpenApiDocument, YamlScalarsKeepTheirTypes) {
  const json& straight = doc()["components"]["schemas"]["StraightContour"]["properties"];
  EXPECT_TRUE(straight["width_mm"]["maximum"].is_number_integer());
  EXPECT_EQ(straight["width_mm"]["maximum"], 1000000);
  EXPECT_TRUE(straight["angle_deg"]["maximum"].is_number_float());
  EXPECT_TRUE(straight["contour"]["const"].is_string());
  EXPECT_TRUE(
      doc()["paths"]["/v1/entry-length"]["post"]["responses"].contains("200"));  // quoted key
  EXPECT_TRUE(doc()["paths"]["/v1/entry-length"]["post"]["requestBody"]["required"].is_boolean());
  const json& worked = doc()["paths"]["/v1/main-time"]["post"]["requestBody"]["content"]
                            ["application/json"]["examples"]["worked"]["value"];
  EXPECT_TRUE(worked["feed_per_tooth_mm"].is_number_float());
  EXPECT_EQ(worked["feed_per_tooth_mm"], 0.1);
}

TEST(OpenApiDocument, RejectsUnsupportedSchemaKeywordsAndMissingFiles) {
  EXPECT_THROW(OpenApiContract::load("/nonexistent/openapi.yaml"), std::runtime_error);
  const std::string path = ::testing::TempDir() + "openapi_unsupported_keyword.yaml";
  {
    std::ofstream out(path);
    out << "openapi: 3.1.0\ninfo: {title: t, version: '1'}\npaths: {}\n"
           "components:\n  schemas:\n    A:\n      type: array\n      uniqueItem: true\n"
           "    B:\n      $ref: '#/components/schemas/Missing'\n";
  }
  try {
    OpenApiContract::load(path);
    ADD_FAILURE() << "load accepted an unknown keyword and a dangling $ref";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("uniqueItem"), std::string::npos) << what;  // a typo: no such keyword
    EXPECT_NE(what.find("Missing"), std::string::npos) << what;
  }
}

TEST(OpenApiDocument, EveryRequestExampleMatchesItsSchema) {
  int checked = 0;
  for (const auto& o : operations()) {
    if (!o.op->contains("requestBody")) {
      continue;
    }
    const json& body = deref((*o.op)["requestBody"]);
    for (const auto& [media_type, media] : body["content"].items()) {
      const auto examples = examples_of(media);
      EXPECT_FALSE(examples.empty())
          << o.method << " " << o.path << " " << media_type << " has no request example";
      for (const auto& [name, value] : examples) {
        const auto v = project_contract().check_request(o.method, o.path, value);
        EXPECT_TRUE(v.empty()) << o.method << " " << o.path << " request example " << name
                               << join(v);
        ++checked;
      }
    }
  }
  EXPECT_GE(checked, 13);
}

TEST(OpenApiDocument, EveryResponseExampleMatchesItsSchema) {
  int checked = 0;
  for (const auto& o : operations()) {
    for (const auto& [status, response_ref] : (*o.op)["responses"].items()) {
      const json& response = deref(response_ref);
      if (!response.contains("content")) {
        // Only HEAD's 200 and OPTIONS' 204 have no body.
        EXPECT_TRUE((o.method == "HEAD" && status == "200") ||
                    (o.method == "OPTIONS" && status == "204"))
            << o.method << " " << o.path << " " << status << " has no content";
        continue;
      }
      for (const auto& [media_type, media] : response["content"].items()) {
        const auto examples = examples_of(media);
        EXPECT_FALSE(examples.empty())
            << o.method << " " << o.path << " " << status << " " << media_type << " has no example";
        for (const auto& [name, value] : examples) {
          const auto v = project_contract().check_response(o.method, o.path, std::stoi(status),
                                                           media_type, value);
          EXPECT_TRUE(v.empty()) << o.method << " " << o.path << " " << status << " example "
                                 << name << join(v);
          ++checked;
        }
      }
    }
  }
  const json& unmatched = doc()["x-cutcalc-unmatched-route"]["response"]["content"];
  for (const auto& [media_type, media] : unmatched.items()) {
    for (const auto& [name, value] : examples_of(media)) {
      const auto v =
          project_contract().check_response("GET", "/no/such/route", 404, media_type, value);
      EXPECT_TRUE(v.empty()) << "404 example " << name << join(v);
      ++checked;
    }
  }
  EXPECT_GE(checked, 70);
}

TEST(OpenApiDocument, EveryOperationHasAUniqueOperationIdSummaryDescriptionAndTag) {
  std::set<std::string> ids;
  for (const auto& o : operations()) {
    ASSERT_TRUE(o.op->contains("operationId")) << o.method << " " << o.path;
    const std::string id = (*o.op)["operationId"].get<std::string>();
    EXPECT_TRUE(ids.insert(id).second) << "duplicate operationId " << id;
    EXPECT_TRUE(o.op->contains("summary")) << id;
    EXPECT_TRUE(o.op->contains("description")) << id;
    ASSERT_TRUE(o.op->contains("tags")) << id;
    EXPECT_FALSE((*o.op)["tags"].empty()) << id;
  }
  // 18 paths (10 calculations, 5 operations, the web page, its top assets and its modules), each
  // with OPTIONS; the 8 GET paths with HEAD.
  EXPECT_EQ(ids.size(), 18U + 18U + 8U);
}

TEST(OpenApiDocument, JsonBodyOperationsDocumentEveryErrorStatusAsProblemJson) {
  int json_body_operations = 0;
  for (const auto& o : operations()) {
    if (!o.op->contains("requestBody")) {
      continue;
    }
    const json& body = deref((*o.op)["requestBody"]);
    if (!body["content"].contains("application/json")) {
      continue;
    }
    ++json_body_operations;
    EXPECT_TRUE(body.value("required", false)) << o.path;
    const json& responses = (*o.op)["responses"];
    for (const char* status : {"400", "413", "415", "422", "500"}) {
      ASSERT_TRUE(responses.contains(status)) << o.method << " " << o.path << " lacks " << status;
      const json& response = deref(responses[status]);
      EXPECT_TRUE(response["content"].contains("application/problem+json"))
          << o.path << " " << status;
    }
  }
  EXPECT_EQ(json_body_operations, 10);
}

TEST(OpenApiDocument, EveryResponseCarriesXRequestIdAndEveryOperationAcceptsIt) {
  for (const auto& o : operations()) {
    bool takes_request_id = false;
    for (const auto& p : (*o.op)["parameters"]) {
      const json& param = deref(p);
      takes_request_id =
          takes_request_id || (param["name"] == "X-Request-Id" && param["in"] == "header" &&
                               !param.value("required", false));
    }
    EXPECT_TRUE(takes_request_id) << o.method << " " << o.path;
    for (const auto& [status, response_ref] : (*o.op)["responses"].items()) {
      const json& response = deref(response_ref);
      ASSERT_TRUE(response.contains("headers")) << o.path << " " << status;
      EXPECT_TRUE(deref(response["headers"]["X-Request-Id"]).value("required", false))
          << o.path << " " << status;
    }
  }
}

TEST(OpenApiDocument, CheckerRejectsWrongTypeMissingRequiredFieldAndExtraField) {
  const json good = entry_length_body();
  ASSERT_TRUE(project_contract()
                  .check_response("POST", "/v1/entry-length", 200, "application/json", good)
                  .empty());

  json wrong_type = good;
  wrong_type["start"]["x_mm"] = "27.0";
  auto v = project_contract().check_response("POST", "/v1/entry-length", 200, "application/json",
                                             wrong_type);
  EXPECT_TRUE(names_pointer(v, "/start/x_mm")) << join(v);

  json missing = good;
  missing.erase("steady_width_mm");
  v = project_contract().check_response("POST", "/v1/entry-length", 200, "application/json",
                                        missing);
  EXPECT_FALSE(v.empty());
  EXPECT_TRUE(names_pointer(v, "/steady_width_mm")) << join(v);

  json extra = good;
  extra["steady_width"] = 25.0;
  v = project_contract().check_response("POST", "/v1/entry-length", 200, "application/json", extra);
  EXPECT_TRUE(names_pointer(v, "/steady_width")) << join(v);

  json nested_extra = good;
  nested_extra["end"]["z_mm"] = 0.0;
  v = project_contract().check_response("POST", "/v1/entry-length", 200, "application/json",
                                        nested_extra);
  EXPECT_TRUE(names_pointer(v, "/end/z_mm")) << join(v);

  json negative = good;
  negative["entry_length_mm"] = -1.0;
  v = project_contract().check_response("POST", "/v1/entry-length", 200, "application/json",
                                        negative);
  EXPECT_TRUE(names_pointer(v, "/entry_length_mm")) << join(v);

  json end_without_stroke = good;
  end_without_stroke.erase("working_stroke_mm");
  v = project_contract().check_response("POST", "/v1/entry-length", 200, "application/json",
                                        end_without_stroke);
  EXPECT_FALSE(v.empty()) << "end without working_stroke_mm must be rejected";

  json without_exit = good;
  without_exit.erase("working_stroke_mm");
  without_exit.erase("end");
  EXPECT_TRUE(project_contract()
                  .check_response("POST", "/v1/entry-length", 200, "application/json", without_exit)
                  .empty());

  json lateral =
      json::parse(R"({"spindle_speed_rpm": 1000.0, "feed_per_rev_mm": 0.4, "feed_mm_per_min": 400.0,
    "entry_feed_mm_per_min": 200.0, "depth_passes_mm": [2.0], "lateral_passes": [{"width_mm": 45.0}],
    "main_time_min": 1, "entry_time_min": 0.5, "steady_time_min": 0.5})");
  v = project_contract().check_response("POST", "/v1/main-time", 200, "application/json", lateral);
  EXPECT_TRUE(names_pointer(v, "/lateral_passes/0")) << join(v);
}

TEST(OpenApiDocument, CheckerRejectsUndocumentedPathsOperationsStatusesAndMediaTypes) {
  const json body = entry_length_body();
  EXPECT_FALSE(project_contract()
                   .check_response("POST", "/v1/entry-lengths", 200, "application/json", body)
                   .empty());
  EXPECT_FALSE(project_contract()
                   .check_response("PUT", "/v1/entry-length", 200, "application/json", body)
                   .empty());
  EXPECT_FALSE(project_contract()
                   .check_response("POST", "/v1/entry-length", 201, "application/json", body)
                   .empty());
  EXPECT_FALSE(project_contract()
                   .check_response("POST", "/v1/entry-length", 200, "text/html", body)
                   .empty());
  EXPECT_FALSE(
      project_contract().check_response("POST", "/v1/entry-length", 200, "", body).empty());
  EXPECT_TRUE(project_contract()
                  .check_response("post", "/v1/entry-length", 200, "application/json", body)
                  .empty());
  // Media types match exactly, parameters included (as strict generated clients match them).
  EXPECT_FALSE(
      project_contract()
          .check_response("POST", "/v1/entry-length", 200, "application/json; charset=utf-8", body)
          .empty());
  // A success body is not a problem body, and the other way round.
  EXPECT_FALSE(
      project_contract()
          .check_response("POST", "/v1/entry-length", 200, "application/problem+json", body)
          .empty());
  EXPECT_FALSE(
      project_contract()
          .check_response("POST", "/v1/entry-length", 422, "application/json",
                          problem("urn:cutcalc:problem:invalid-input", "Invalid input", 422,
                                  json::array({{{"pointer", "/entry"}, {"detail", "required"}}})))
          .empty());
}

TEST(OpenApiDocument, ProblemSchemasPinTypeStatusAndErrorCodes) {
  const std::string pj = "application/problem+json";
  const json field_error = json::array(
      {{{"pointer", "/entry/width_mm"}, {"code", "must_be_positive"}, {"detail", "must be > 0"}}});
  const json combination =
      json::array({{{"pointer", ""}, {"code", "no_contact"}, {"detail", "no contact"}}});
  EXPECT_TRUE(project_contract()
                  .check_response("POST", "/v1/main-time", 422, pj,
                                  problem("urn:cutcalc:problem:invalid-input", "Invalid input", 422,
                                          field_error))
                  .empty());
  EXPECT_TRUE(project_contract()
                  .check_response("POST", "/v1/main-time", 422, pj,
                                  problem("urn:cutcalc:problem:impossible-input",
                                          "Input impossible for the model", 422, combination))
                  .empty());
  // An error without its code or with an unknown one, wrong type for the status, wrong status,
  // no errors, bad pointer. (Titles are not pinned: they follow Accept-Language.)
  json without_code = field_error;
  without_code[0].erase("code");
  EXPECT_FALSE(project_contract()
                   .check_response("POST", "/v1/main-time", 422, pj,
                                   problem("urn:cutcalc:problem:invalid-input", "Invalid input",
                                           422, without_code))
                   .empty());
  json unknown_code = field_error;
  unknown_code[0]["code"] = "must_be_nice";
  EXPECT_FALSE(project_contract()
                   .check_response("POST", "/v1/main-time", 422, pj,
                                   problem("urn:cutcalc:problem:invalid-input", "Invalid input",
                                           422, unknown_code))
                   .empty());
  EXPECT_FALSE(project_contract()
                   .check_response("POST", "/v1/main-time", 422, pj,
                                   problem("urn:cutcalc:problem:malformed-json", "Malformed JSON",
                                           422, field_error))
                   .empty());
  EXPECT_FALSE(
      project_contract()
          .check_response("POST", "/v1/main-time", 400, pj,
                          problem("urn:cutcalc:problem:malformed-json", "Malformed JSON", 422))
          .empty());
  EXPECT_FALSE(
      project_contract()
          .check_response("POST", "/v1/main-time", 422, pj,
                          problem("urn:cutcalc:problem:invalid-input", "Invalid input", 422))
          .empty());
  auto v = project_contract().check_response(
      "POST", "/v1/main-time", 422, pj,
      problem("urn:cutcalc:problem:invalid-input", "Invalid input", 422,
              json::array({{{"pointer", "entry"}, {"detail", "not a JSON Pointer"}}})));
  EXPECT_TRUE(names_pointer(v, "/errors/0/pointer")) << join(v);
  json no_errors = problem("urn:cutcalc:problem:payload-too-large", "Payload too large", 413);
  no_errors.erase("errors");
  v = project_contract().check_response("POST", "/v1/main-time", 413, pj, no_errors);
  EXPECT_TRUE(names_pointer(v, "/errors")) << join(v);
  json with_extension =
      problem("urn:cutcalc:problem:unsupported-media-type", "Unsupported media type", 415);
  EXPECT_TRUE(
      project_contract().check_response("POST", "/v1/main-time", 415, pj, with_extension).empty());
  with_extension["hint"] = "use application/json";
  v = project_contract().check_response("POST", "/v1/main-time", 415, pj, with_extension);
  EXPECT_TRUE(names_pointer(v, "/hint")) << join(v);
  json float_status = problem("urn:cutcalc:problem:internal-error", "Internal error", 500);
  float_status["status"] = 500.5;
  v = project_contract().check_response("POST", "/v1/main-time", 500, pj, float_status);
  EXPECT_TRUE(names_pointer(v, "/status")) << join(v);
}

TEST(OpenApiDocument, RouteFallbacksCover404And405AndTheirHeaders) {
  const std::string pj = "application/problem+json";
  const json not_found = problem("urn:cutcalc:problem:not-found", "Not found", 404);
  EXPECT_TRUE(project_contract().check_response("GET", "/v1/nope", 404, pj, not_found).empty());
  EXPECT_FALSE(project_contract()
                   .check_response("GET", "/v1/nope", 404, pj,
                                   problem("urn:cutcalc:problem:internal-error", "Not found", 404))
                   .empty());
  EXPECT_FALSE(project_contract()
                   .check_response("GET", "/v1/nope", 200, "application/json", json::object())
                   .empty());

  const json not_allowed =
      problem("urn:cutcalc:problem:method-not-allowed", "Method not allowed", 405);
  EXPECT_TRUE(
      project_contract().check_response("GET", "/v1/entry-length", 405, pj, not_allowed).empty());
  EXPECT_TRUE(project_contract().check_response("POST", "/healthz", 405, pj, not_allowed).empty());
  EXPECT_TRUE(
      project_contract()
          .check_response_headers(
              "GET", "/v1/entry-length", 405,
              {{"allow", "POST, OPTIONS"}, {"x-request-id", "a.b-c_1"}, {"content-language", "en"}})
          .empty());
  auto v = project_contract().check_response_headers(
      "GET", "/v1/entry-length", 405, {{"X-Request-Id", "abc"}, {"Content-Language", "ru"}});
  EXPECT_EQ(v.size(), 1U) << join(v);  // Allow is missing
  v = project_contract().check_response_headers("POST", "/v1/entry-length", 200, {});
  EXPECT_EQ(v.size(), 1U) << join(v);  // X-Request-Id is missing
  v = project_contract().check_response_headers("POST", "/v1/entry-length", 200,
                                                {{"X-Request-Id", "has space"}});
  EXPECT_EQ(v.size(), 1U) << join(v);
  v = project_contract().check_response_headers("POST", "/v1/entry-length", 200,
                                                {{"X-Request-Id", std::string(129, 'a')}});
  EXPECT_EQ(v.size(), 1U) << join(v);
  EXPECT_TRUE(project_contract()
                  .check_response_headers("POST", "/v1/entry-length", 200,
                                          {{"X-Request-Id", std::string(128, 'a')}})
                  .empty());
}

TEST(OpenApiDocument, OperationalResponsesAreStrict) {
  EXPECT_TRUE(project_contract()
                  .check_response("GET", "/healthz", 200, "application/json", {{"status", "ok"}})
                  .empty());
  EXPECT_FALSE(
      project_contract()
          .check_response("GET", "/healthz", 200, "application/json", {{"status", "ready"}})
          .empty());
  EXPECT_TRUE(project_contract()
                  .check_response("GET", "/readyz", 200, "application/json", {{"status", "ready"}})
                  .empty());
  EXPECT_TRUE(
      project_contract()
          .check_response("GET", "/readyz", 503, "application/problem+json",
                          problem("urn:cutcalc:problem:unavailable", "Service unavailable", 503))
          .empty());
  const json version = {
      {"name", "cutcalc"}, {"version", "0.1.0"}, {"commit", "unknown"}, {"build_type", "Release"}};
  EXPECT_TRUE(project_contract()
                  .check_response("GET", "/version", 200, "application/json", version)
                  .empty());
  json bad_version = version;
  bad_version["commit"] = "not a sha";
  EXPECT_TRUE(names_pointer(
      project_contract().check_response("GET", "/version", 200, "application/json", bad_version),
      "/commit"));
  EXPECT_TRUE(project_contract()
                  .check_response("GET", "/metrics", 200,
                                  "text/plain; version=0.0.4; charset=utf-8", "# metrics\n")
                  .empty());
  EXPECT_FALSE(project_contract()
                   .check_response("GET", "/metrics", 200, "text/plain", "# metrics\n")
                   .empty());
  EXPECT_TRUE(
      project_contract()
          .check_response("GET", "/openapi.yaml", 200, "application/yaml", "openapi: 3.1.0\n")
          .empty());
}

TEST(OpenApiDocument, RequestSchemaEnforcesContourRules) {
  const json base = json::parse(R"({"cutter_diameter_mm": 20,
    "entry": {"contour": "straight", "width_mm": 60}})");
  EXPECT_TRUE(project_contract().check_request("POST", "/v1/entry-length", base).empty());

  json wall_entry = base;
  wall_entry["entry"] = {{"contour", "wall"}, {"width_mm", 60}};
  auto v = project_contract().check_request("POST", "/v1/entry-length", wall_entry);
  EXPECT_TRUE(names_pointer(v, "/entry/contour")) << join(v);

  json with_wall_exit = base;
  with_wall_exit["exit"] = {{"contour", "wall"}, {"width_mm", 60}};
  with_wall_exit["length_mm"] = 100;
  EXPECT_TRUE(project_contract().check_request("POST", "/v1/entry-length", with_wall_exit).empty());

  json radius_on_straight = base;
  radius_on_straight["entry"]["radius_mm"] = 10;
  v = project_contract().check_request("POST", "/v1/entry-length", radius_on_straight);
  EXPECT_TRUE(names_pointer(v, "/entry/radius_mm")) << join(v);

  json angle = base;
  angle["entry"]["angle_deg"] = 180;
  v = project_contract().check_request("POST", "/v1/entry-length", angle);
  EXPECT_TRUE(names_pointer(v, "/entry/angle_deg")) << join(v);

  json concave_without_width = base;
  concave_without_width["entry"] = {{"contour", "concave_arc"}, {"radius_mm", 30}};
  v = project_contract().check_request("POST", "/v1/entry-length", concave_without_width);
  EXPECT_TRUE(names_pointer(v, "/entry/width_mm")) << join(v);

  json convex_without_width = base;
  convex_without_width["entry"] = {{"contour", "convex_arc"}, {"radius_mm", 30}};
  EXPECT_TRUE(
      project_contract().check_request("POST", "/v1/entry-length", convex_without_width).empty());

  json exit_without_length = base;
  exit_without_length["exit"] = base["entry"];
  EXPECT_FALSE(
      project_contract().check_request("POST", "/v1/entry-length", exit_without_length).empty());

  json length_without_exit = base;
  length_without_exit["length_mm"] = 100;
  EXPECT_FALSE(
      project_contract().check_request("POST", "/v1/entry-length", length_without_exit).empty());

  json negative_approach = base;
  negative_approach["approach_mm"] = -0.5;
  v = project_contract().check_request("POST", "/v1/entry-length", negative_approach);
  EXPECT_TRUE(names_pointer(v, "/approach_mm")) << join(v);

  EXPECT_TRUE(names_pointer(
      project_contract().check_request("POST", "/v1/entry-length", json::array()), ""));
}

TEST(OpenApiDocument, RequestSchemaEnforcesMainTimeCombinations) {
  const json good = main_time_request();
  ASSERT_TRUE(project_contract().check_request("POST", "/v1/main-time", good).empty())
      << join(project_contract().check_request("POST", "/v1/main-time", good));

  json both_speeds = good;
  both_speeds["cutting_speed_m_per_min"] = 150;
  EXPECT_FALSE(project_contract().check_request("POST", "/v1/main-time", both_speeds).empty());

  json no_speed = good;
  no_speed.erase("spindle_speed_rpm");
  EXPECT_FALSE(project_contract().check_request("POST", "/v1/main-time", no_speed).empty());

  json cutting_speed = no_speed;
  cutting_speed["cutting_speed_m_per_min"] = 150;
  EXPECT_TRUE(project_contract().check_request("POST", "/v1/main-time", cutting_speed).empty());

  json both_entry_feeds = good;
  both_entry_feeds["entry_feed_per_tooth_mm"] = 0.05;
  EXPECT_FALSE(project_contract().check_request("POST", "/v1/main-time", both_entry_feeds).empty());

  json entry_feed_per_tooth = both_entry_feeds;
  entry_feed_per_tooth.erase("entry_feed_factor");
  EXPECT_TRUE(
      project_contract().check_request("POST", "/v1/main-time", entry_feed_per_tooth).empty());

  json factor = good;
  factor["entry_feed_factor"] = 1.0;
  EXPECT_TRUE(project_contract().check_request("POST", "/v1/main-time", factor).empty());
  factor["entry_feed_factor"] = 1.01;
  EXPECT_TRUE(names_pointer(project_contract().check_request("POST", "/v1/main-time", factor),
                            "/entry_feed_factor"));
  factor["entry_feed_factor"] = 0;
  EXPECT_TRUE(names_pointer(project_contract().check_request("POST", "/v1/main-time", factor),
                            "/entry_feed_factor"));

  json teeth = good;
  teeth["teeth"] = 2.0;
  EXPECT_TRUE(project_contract().check_request("POST", "/v1/main-time", teeth).empty());
  teeth["teeth"] = 2.5;
  EXPECT_TRUE(
      names_pointer(project_contract().check_request("POST", "/v1/main-time", teeth), "/teeth"));
  teeth["teeth"] = 0;
  EXPECT_TRUE(
      names_pointer(project_contract().check_request("POST", "/v1/main-time", teeth), "/teeth"));

  json missing_allowance_member = good;
  missing_allowance_member["allowance"].erase("depth_mm");
  EXPECT_TRUE(names_pointer(
      project_contract().check_request("POST", "/v1/main-time", missing_allowance_member),
      "/allowance/depth_mm"));

  json wall_exit = good;
  wall_exit["exit"] = {{"contour", "wall"}, {"width_mm", 80}};
  EXPECT_TRUE(project_contract().check_request("POST", "/v1/main-time", wall_exit).empty());

  json no_exit = good;
  no_exit.erase("exit");
  EXPECT_TRUE(
      names_pointer(project_contract().check_request("POST", "/v1/main-time", no_exit), "/exit"));
}

TEST(OpenApiDocument, RequestSchemaEnforcesResultantSpeedsRules) {
  const std::string path = "/v1/resultant-speeds";
  const json good = resultant_speeds_request();
  ASSERT_TRUE(project_contract().check_request("POST", path, good).empty())
      << join(project_contract().check_request("POST", path, good));

  // Exactly one of center_distance_mm and flat_depth_mm: both or neither is rejected at "".
  json both = good;
  both["center_distance_mm"] = 25.0;
  auto v = project_contract().check_request("POST", path, both);
  EXPECT_TRUE(names_pointer(v, "")) << join(v);

  json neither = good;
  neither.erase("flat_depth_mm");
  v = project_contract().check_request("POST", path, neither);
  EXPECT_TRUE(names_pointer(v, "")) << join(v);

  json center_distance = neither;
  center_distance["center_distance_mm"] = 25.5;
  EXPECT_TRUE(project_contract().check_request("POST", path, center_distance).empty());

  json zero_distance = neither;
  zero_distance["center_distance_mm"] = 0;
  v = project_contract().check_request("POST", path, zero_distance);
  EXPECT_TRUE(names_pointer(v, "/center_distance_mm")) << join(v);

  // A still workpiece and a feed towards the workpiece axis are valid; a still tool is not.
  json still = good;
  still["workpiece_speed_rpm"] = 0;
  still["tool_feed_mm_per_min"] = -100;
  EXPECT_TRUE(project_contract().check_request("POST", path, still).empty());
  json still_tool = good;
  still_tool["tool_speed_rpm"] = 0;
  EXPECT_TRUE(
      names_pointer(project_contract().check_request("POST", path, still_tool), "/tool_speed_rpm"));
  json feed_cap = good;
  feed_cap["tool_feed_mm_per_min"] = -1000001;
  EXPECT_TRUE(names_pointer(project_contract().check_request("POST", path, feed_cap),
                            "/tool_feed_mm_per_min"));

  json milling = good;
  milling["milling"] = "climb";
  EXPECT_TRUE(names_pointer(project_contract().check_request("POST", path, milling), "/milling"));
  milling.erase("milling");
  EXPECT_TRUE(names_pointer(project_contract().check_request("POST", path, milling), "/milling"));

  json angles = good;
  angles["contact_angles_deg"] = json::array({-5, 5, 0, 20.281649812950175, 5});
  EXPECT_TRUE(project_contract().check_request("POST", path, angles).empty());
  angles["contact_angles_deg"] = json::array();
  EXPECT_TRUE(
      names_pointer(project_contract().check_request("POST", path, angles), "/contact_angles_deg"));
  angles["contact_angles_deg"] = json(std::vector<double>(1001, 0.0));
  EXPECT_TRUE(
      names_pointer(project_contract().check_request("POST", path, angles), "/contact_angles_deg"));
  angles["contact_angles_deg"] = json::array({0, "10"});
  EXPECT_TRUE(names_pointer(project_contract().check_request("POST", path, angles),
                            "/contact_angles_deg/1"));
  angles["contact_angles_deg"] = 0;
  EXPECT_TRUE(
      names_pointer(project_contract().check_request("POST", path, angles), "/contact_angles_deg"));

  json lambda = good;
  lambda["edge_inclination_deg"] = -89.999;
  EXPECT_TRUE(project_contract().check_request("POST", path, lambda).empty());
  for (const double bad : {90.0, -90.0}) {
    lambda["edge_inclination_deg"] = bad;
    EXPECT_TRUE(names_pointer(project_contract().check_request("POST", path, lambda),
                              "/edge_inclination_deg"))
        << bad;
  }
}

TEST(OpenApiDocument, RequestSchemaEnforcesGrooveWallRules) {
  const std::string path = "/v1/roughness/groove-wall";
  const json good = groove_wall_request();
  ASSERT_TRUE(project_contract().check_request("POST", path, good).empty())
      << join(project_contract().check_request("POST", path, good));

  json no_target = good;
  no_target.erase("target_rz_um");
  EXPECT_TRUE(project_contract().check_request("POST", path, no_target).empty());

  // phi1 = 0 is valid on its own (Rz = 0) but has no largest feed for a target.
  json flat_minor_edge = no_target;
  flat_minor_edge["minor_edge_angle_deg"] = 0;
  EXPECT_TRUE(project_contract().check_request("POST", path, flat_minor_edge).empty());
  for (const json& zero : {json(0), json(0.0)}) {
    json target_without_angle = good;
    target_without_angle["minor_edge_angle_deg"] = zero;
    const auto v = project_contract().check_request("POST", path, target_without_angle);
    EXPECT_TRUE(names_pointer(v, "")) << zero.dump() << join(v);
  }

  json angle = good;
  angle["minor_edge_angle_deg"] = 89.9;
  EXPECT_TRUE(project_contract().check_request("POST", path, angle).empty());
  angle["minor_edge_angle_deg"] = 90;
  EXPECT_TRUE(names_pointer(project_contract().check_request("POST", path, angle),
                            "/minor_edge_angle_deg"));
  angle["minor_edge_angle_deg"] = -0.1;
  EXPECT_TRUE(names_pointer(project_contract().check_request("POST", path, angle),
                            "/minor_edge_angle_deg"));

  json target = good;
  target["target_rz_um"] = 0;
  EXPECT_TRUE(
      names_pointer(project_contract().check_request("POST", path, target), "/target_rz_um"));
  target["target_rz_um"] = 1.0e9;
  EXPECT_TRUE(project_contract().check_request("POST", path, target).empty());
  target["target_rz_um"] = 1.1e9;
  EXPECT_TRUE(
      names_pointer(project_contract().check_request("POST", path, target), "/target_rz_um"));

  json missing = good;
  missing.erase("feed_mm");
  EXPECT_TRUE(names_pointer(project_contract().check_request("POST", path, missing), "/feed_mm"));
}

TEST(OpenApiDocument, RequestSchemaEnforcesBoreMillingRules) {
  const std::string path = "/v1/roughness/bore-milling";
  const json good = bore_milling_request();
  ASSERT_TRUE(project_contract().check_request("POST", path, good).empty())
      << join(project_contract().check_request("POST", path, good));

  json teeth = good;
  teeth["teeth"] = 2.0;
  EXPECT_TRUE(project_contract().check_request("POST", path, teeth).empty());
  for (const json& bad : {json(2.5), json(0), json(1001), json("4")}) {
    teeth["teeth"] = bad;
    EXPECT_TRUE(names_pointer(project_contract().check_request("POST", path, teeth), "/teeth"))
        << bad.dump();
  }

  json feed = good;
  feed["feed_per_rev_mm"] = 0;
  EXPECT_TRUE(
      names_pointer(project_contract().check_request("POST", path, feed), "/feed_per_rev_mm"));

  json milling = good;
  milling["milling"] = "down";
  EXPECT_TRUE(project_contract().check_request("POST", path, milling).empty());
  milling.erase("milling");
  EXPECT_TRUE(names_pointer(project_contract().check_request("POST", path, milling), "/milling"));

  // r < R relates two fields: the schema cannot state it (the service answers 422 at
  // /cutter_radius_mm), so such a request passes the schema.
  json equal_radii = good;
  equal_radii["cutter_radius_mm"] = 81.0;
  EXPECT_TRUE(project_contract().check_request("POST", path, equal_radii).empty());
}

TEST(OpenApiDocument, NewCalculationResponsesAreStrict) {
  const std::string aj = "application/json";
  const json rs = resultant_speeds_body();
  ASSERT_TRUE(
      project_contract().check_response("POST", "/v1/resultant-speeds", 200, aj, rs).empty());
  json missing = rs;
  missing["points"][0].erase("kinematic_ratio");
  auto v = project_contract().check_response("POST", "/v1/resultant-speeds", 200, aj, missing);
  EXPECT_TRUE(names_pointer(v, "/points/0")) << join(v);
  json sense = rs;
  sense["points"][0]["sense"] = "climb";
  v = project_contract().check_response("POST", "/v1/resultant-speeds", 200, aj, sense);
  EXPECT_TRUE(names_pointer(v, "/points/0/sense")) << join(v);
  json negative = rs;
  negative["points"][0]["resultant_speed_m_per_min"] = -1.0;
  v = project_contract().check_response("POST", "/v1/resultant-speeds", 200, aj, negative);
  EXPECT_TRUE(names_pointer(v, "/points/0/resultant_speed_m_per_min")) << join(v);
  json signed_along_edge = rs;
  signed_along_edge["points"][0]["along_edge_speed_m_per_min"] = -93.77;
  signed_along_edge["points"][0]["resultant_angle_deg"] = -179.5;
  EXPECT_TRUE(project_contract()
                  .check_response("POST", "/v1/resultant-speeds", 200, aj, signed_along_edge)
                  .empty());
  json no_points = rs;
  no_points["points"] = json::array();
  EXPECT_TRUE(names_pointer(
      project_contract().check_response("POST", "/v1/resultant-speeds", 200, aj, no_points),
      "/points"));

  const json gw = {{"rz_um", 2.6248327576439583},
                   {"ra_um", 0.7080340459388432},
                   {"branch", "nose_arc_and_minor_edge"},
                   {"max_feed_mm", 0.4712450622448343}};
  EXPECT_TRUE(
      project_contract().check_response("POST", "/v1/roughness/groove-wall", 200, aj, gw).empty());
  json branch = gw;
  branch["branch"] = "minor_edge";
  EXPECT_TRUE(names_pointer(
      project_contract().check_response("POST", "/v1/roughness/groove-wall", 200, aj, branch),
      "/branch"));
  json negative_rz = gw;
  negative_rz["rz_um"] = -0.5;
  EXPECT_TRUE(names_pointer(
      project_contract().check_response("POST", "/v1/roughness/groove-wall", 200, aj, negative_rz),
      "/rz_um"));
  json no_ra = gw;  // ra_um is always in the answer (roughness.md R14)
  no_ra.erase("ra_um");
  EXPECT_TRUE(names_pointer(
      project_contract().check_response("POST", "/v1/roughness/groove-wall", 200, aj, no_ra),
      "/ra_um"));
  json bearing = gw;
  bearing["bearing_curve"] = {{{"depth_um", 1.0}, {"material_ratio", 0.5}},
                              {{"depth_um", 2.0}, {"material_ratio", 1.0}}};
  EXPECT_TRUE(project_contract()
                  .check_response("POST", "/v1/roughness/groove-wall", 200, aj, bearing)
                  .empty());
  bearing["bearing_curve"][1]["material_ratio"] = 1.5;
  EXPECT_TRUE(names_pointer(
      project_contract().check_response("POST", "/v1/roughness/groove-wall", 200, aj, bearing),
      "/bearing_curve/1/material_ratio"));

  const json bm = {{"cusp_height_um", 0.016043564224403145},
                   {"approximate_cusp_height_um", 0.016075102880658436},
                   {"feed_per_tooth_mm", 0.05},
                   {"feed_per_tooth_on_bore_mm", 0.08333333333333333},
                   {"pitch_angle_deg", 0.0589849078927141}};
  EXPECT_TRUE(
      project_contract().check_response("POST", "/v1/roughness/bore-milling", 200, aj, bm).empty());
  json no_pitch = bm;
  no_pitch.erase("pitch_angle_deg");
  EXPECT_TRUE(names_pointer(
      project_contract().check_response("POST", "/v1/roughness/bore-milling", 200, aj, no_pitch),
      "/pitch_angle_deg"));
  json extra = bm;
  extra["cusp_height_mm"] = 1.6e-5;
  EXPECT_TRUE(names_pointer(
      project_contract().check_response("POST", "/v1/roughness/bore-milling", 200, aj, extra),
      "/cusp_height_mm"));
}

TEST(OpenApiDocument, RequestSchemaEnforcesPolygonHoleRules) {
  const std::string path = "/v1/polygon-hole/gcode";
  const json good = polygon_hole_request();
  ASSERT_TRUE(project_contract().check_request("POST", path, good).empty())
      << join(project_contract().check_request("POST", path, good));

  // faces: an integer-valued number 3..12 (spec section 10: 4 and 4.0 accepted).
  json faces = good;
  for (const json& ok : {json(3), json(12), json(4.0)}) {
    faces["faces"] = ok;
    EXPECT_TRUE(project_contract().check_request("POST", path, faces).empty()) << ok.dump();
  }
  for (const json& bad : {json(2), json(13), json(4.5), json("6"), json(nullptr)}) {
    faces["faces"] = bad;
    EXPECT_TRUE(names_pointer(project_contract().check_request("POST", path, faces), "/faces"))
        << bad.dump();
  }

  json diameter = good;
  diameter["inscribed_diameter_mm"] = 1;
  EXPECT_TRUE(project_contract().check_request("POST", path, diameter).empty());
  for (const double bad : {0.999, 0.0, -16.0, 1000001.0}) {
    diameter["inscribed_diameter_mm"] = bad;
    EXPECT_TRUE(names_pointer(project_contract().check_request("POST", path, diameter),
                              "/inscribed_diameter_mm"))
        << bad;
  }

  // A step larger than the depth is one layer, not an error.
  json one_layer = good;
  one_layer["step_down_mm"] = 5.0;
  EXPECT_TRUE(project_contract().check_request("POST", path, one_layer).empty());
  for (const char* field : {"depth_mm", "step_down_mm", "spindle_speed_rpm"}) {
    json positive = good;
    positive[field] = 0;
    EXPECT_TRUE(names_pointer(project_contract().check_request("POST", path, positive),
                              std::string("/") + field))
        << field;
    positive[field] = 1.0e-7;
    EXPECT_TRUE(names_pointer(project_contract().check_request("POST", path, positive),
                              std::string("/") + field))
        << field;
    positive.erase(field);
    EXPECT_TRUE(names_pointer(project_contract().check_request("POST", path, positive),
                              std::string("/") + field))
        << field << " is required";
  }

  json tolerance = good;
  for (const double ok : {0.0001, 0.005, 0.1}) {
    tolerance["tolerance_mm"] = ok;
    EXPECT_TRUE(project_contract().check_request("POST", path, tolerance).empty()) << ok;
  }
  for (const double bad : {0.0, 0.00009, 0.11}) {
    tolerance["tolerance_mm"] = bad;
    EXPECT_TRUE(
        names_pointer(project_contract().check_request("POST", path, tolerance), "/tolerance_mm"))
        << bad;
  }

  json sync = good;
  for (const char* ok : {"feed_per_rev", "c_axis"}) {
    sync["synchronization"] = ok;
    EXPECT_TRUE(project_contract().check_request("POST", path, sync).empty()) << ok;
  }
  sync["synchronization"] = "g95";
  EXPECT_TRUE(
      names_pointer(project_contract().check_request("POST", path, sync), "/synchronization"));

  json loops = good;
  for (const json& ok : {json(1), json(100), json(3.0)}) {
    loops["loops_per_layer"] = ok;
    EXPECT_TRUE(project_contract().check_request("POST", path, loops).empty()) << ok.dump();
  }
  for (const json& bad : {json(0), json(101), json(1.5)}) {
    loops["loops_per_layer"] = bad;
    EXPECT_TRUE(
        names_pointer(project_contract().check_request("POST", path, loops), "/loops_per_layer"))
        << bad.dump();
  }

  for (const char* field : {"safe_z_mm", "block_time_ms"}) {
    json positive = good;
    positive[field] = 0.5;
    EXPECT_TRUE(project_contract().check_request("POST", path, positive).empty()) << field;
    positive[field] = 0;
    EXPECT_TRUE(names_pointer(project_contract().check_request("POST", path, positive),
                              std::string("/") + field))
        << field;
  }

  json typo = good;
  typo["tolerence_mm"] = 0.001;
  EXPECT_TRUE(names_pointer(project_contract().check_request("POST", path, typo), "/tolerence_mm"));
}

// `good` (a real 200 answer of `path`, without optional members) matches its schema, and each of
// its members is required: the answer without it is refused at that member.
void expect_valid_with_every_member_required(const std::string& path, const json& good) {
  const std::string aj = "application/json";
  ASSERT_TRUE(project_contract().check_response("POST", path, 200, aj, good).empty())
      << join(project_contract().check_response("POST", path, 200, aj, good));
  for (const auto& [key, unused] : good.items()) {
    json missing = good;
    missing.erase(key);
    EXPECT_TRUE(
        names_pointer(project_contract().check_response("POST", path, 200, aj, missing), "/" + key))
        << key << " must be required";
  }
}

TEST(OpenApiDocument, PolygonHoleAnswersJsonOrThePlainProgram) {
  const std::string path = "/v1/polygon-hole/gcode";
  const std::string aj = "application/json";
  const std::string text = "text/plain; charset=us-ascii";
  const json good = polygon_hole_body();
  expect_valid_with_every_member_required(path, good);
  if (::testing::Test::HasFatalFailure()) return;
  json no_warnings = good;
  no_warnings["warnings"] = json::array();
  EXPECT_TRUE(project_contract().check_response("POST", path, 200, aj, no_warnings).empty());
  json both_warnings = good;
  both_warnings["warnings"].push_back(
      {{"code", "feed_exceeds_block_rate"}, {"detail", "x"}, {"message", "y"}});
  EXPECT_TRUE(project_contract().check_response("POST", path, 200, aj, both_warnings).empty());
  json bad_code = good;
  bad_code["warnings"][0]["code"] = "phase_slip";
  EXPECT_TRUE(names_pointer(project_contract().check_response("POST", path, 200, aj, bad_code),
                            "/warnings/0/code"));
  json no_detail = good;
  no_detail["warnings"][0].erase("detail");
  EXPECT_TRUE(names_pointer(project_contract().check_response("POST", path, 200, aj, no_detail),
                            "/warnings/0/detail"));
  json no_message = good;
  no_message["warnings"][0].erase("message");
  EXPECT_TRUE(names_pointer(project_contract().check_response("POST", path, 200, aj, no_message),
                            "/warnings/0/message"));
  json negative = good;
  negative["corner_gap_mm"] = -0.1;
  EXPECT_TRUE(names_pointer(project_contract().check_response("POST", path, 200, aj, negative),
                            "/corner_gap_mm"));
  json blocks = good;
  blocks["blocks_per_loop"] = 0;
  EXPECT_TRUE(names_pointer(project_contract().check_response("POST", path, 200, aj, blocks),
                            "/blocks_per_loop"));
  blocks["blocks_per_loop"] = 24.5;
  EXPECT_TRUE(names_pointer(project_contract().check_response("POST", path, 200, aj, blocks),
                            "/blocks_per_loop"));
  json extra = good;
  extra["side_mm"] = 16.0;
  EXPECT_TRUE(
      names_pointer(project_contract().check_response("POST", path, 200, aj, extra), "/side_mm"));
  json not_a_program = good;
  not_a_program["program"] = "G21 G17 G90\nM30\n";
  EXPECT_TRUE(names_pointer(project_contract().check_response("POST", path, 200, aj, not_a_program),
                            "/program"));

  // The plain answer: exactly the media type the service sends, a string body with the header.
  const std::string program = polygon_program(4, 16.0);
  EXPECT_TRUE(project_contract().check_response("POST", path, 200, text, program).empty())
      << join(project_contract().check_response("POST", path, 200, text, program));
  EXPECT_TRUE(project_contract()
                  .check_response("POST", path, 200, "text/plain; charset=US-ASCII", program)
                  .empty());
  EXPECT_FALSE(project_contract().check_response("POST", path, 200, "text/plain", program).empty());
  EXPECT_FALSE(project_contract()
                   .check_response("POST", path, 200, "text/plain; charset=utf-8", program)
                   .empty());
  EXPECT_FALSE(project_contract().check_response("POST", path, 200, text, good).empty());
  EXPECT_FALSE(project_contract().check_response("POST", path, 200, text, "M30\n").empty());
  EXPECT_FALSE(project_contract().check_response("POST", path, 200, aj, program).empty());
  EXPECT_TRUE(
      project_contract().check_response("POST", path, 200, text, polygon_program(12, 1.0)).empty());
  EXPECT_FALSE(
      project_contract().check_response("POST", path, 200, text, polygon_program(13, 1.0)).empty());

  // Content-Disposition: optional (absent with JSON), its file name fixed by N and d.
  EXPECT_TRUE(project_contract()
                  .check_response_headers("POST", path, 200, {{"X-Request-Id", "abc"}})
                  .empty());
  EXPECT_TRUE(
      project_contract()
          .check_response_headers(
              "POST", path, 200,
              {{"X-Request-Id", "abc"},
               {"content-disposition", R"(attachment; filename="polygon-hole-N4-d16.0000.ngc")"}})
          .empty());
  for (const char* bad : {R"(attachment; filename="polygon-hole-N4-d16.ngc")",
                          R"(inline; filename="polygon-hole-N4-d16.0000.ngc")",
                          R"(attachment; filename="polygon-hole-N2-d16.0000.ngc")"}) {
    EXPECT_EQ(project_contract()
                  .check_response_headers("POST", path, 200,
                                          {{"X-Request-Id", "abc"}, {"Content-Disposition", bad}})
                  .size(),
              1U)
        << bad;
  }

  // Errors are problem+json whatever Accept asked for; both 422 kinds are documented.
  const std::string pj = "application/problem+json";
  const json field_errors = json::array({{{"pointer", "/faces"},
                                          {"code", "out_of_range"},
                                          {"detail", "must be in [3, 12]"},
                                          {"minimum", 3},
                                          {"maximum", 12}}});
  EXPECT_TRUE(project_contract()
                  .check_response("POST", path, 422, pj,
                                  problem("urn:cutcalc:problem:invalid-input", "Invalid input", 422,
                                          field_errors))
                  .empty());
  EXPECT_TRUE(
      project_contract()
          .check_response(
              "POST", path, 422, pj,
              problem("urn:cutcalc:problem:impossible-input", "Input impossible for the model", 422,
                      json::array({{{"pointer", "/step_down_mm"},
                                    {"code", "program_too_large"},
                                    {"detail", "more than 200000 arc blocks"}}})))
          .empty());
  EXPECT_FALSE(project_contract().check_response("POST", path, 422, text, "(ERROR)").empty());
  EXPECT_TRUE(
      project_contract()
          .check_response_headers(
              "GET", path, 405,
              {{"Allow", "POST, OPTIONS"}, {"X-Request-Id", "a"}, {"Content-Language", "en"}})
          .empty());
  for (const int status : {400, 405, 413, 415, 500, 503}) {
    const json& response = deref(doc()["paths"][path]["post"]["responses"][std::to_string(status)]);
    EXPECT_TRUE(response["content"].contains(pj)) << status;
    EXPECT_EQ(response["content"].size(), 1U) << status;
  }
}

// The lathe programs (/v1/lathe-flat, /v1/grooving/cycle) checked with their real answers: each
// endpoint's handler, the pipeline HTTP answers with (support/endpoint_probe.h).

// lathe-flat.md section 9: D32, t = 1, point tool, N = 10, f = 100 mm/min.
json lathe_flat_request() {
  return json::parse(
      R"({"part_diameter_mm": 32, "flat_depth_mm": 1, "steps": 10, "feed_mm_per_min": 100})");
}

// grooving-cycle.md section 7's worked example (reference case gc-paper-S0.12-css).
json grooving_cycle_request() {
  return json::parse(R"({"groove_width_mm": 10.4, "start_diameter_mm": 220, "groove_depth_mm": 4.8,
    "groove_left_z_mm": -20, "shift_mm": 0.4, "cutting_speed_m_per_min": 86,
    "max_spindle_rpm": 1000, "nose_radius_mm": 0.3, "minor_edge_angle_deg": 2,
    "feed_per_rev_mm": 0.12})");
}

const EndpointProbe kLatheFlat{cutcalc::testing::kLatheFlatPath,
                               &cutcalc::api::lathe_flat::handle_lathe_flat};
const EndpointProbe kGroovingCycle{cutcalc::testing::kGroovingCyclePath,
                                   &cutcalc::api::grooving::handle_grooving_cycle};

// An answer's headers as the service sends them (it adds X-Request-Id to every answer).
std::map<std::string, std::string> headers_of(const cutcalc::api::ApiResponse& response) {
  std::map<std::string, std::string> headers{{"X-Request-Id", "abc-1"}};
  for (const auto& [name, value] : response.headers) {
    headers[name] = value;
  }
  return headers;
}

// The real answers to `request` in each of `dialects` and both units, JSON and text/plain (the
// program alone, exactly the media type sent, as a download), satisfy the contract.
void expect_real_answers_conform(const std::string& path, const EndpointProbe& endpoint,
                                 const json& request, const std::vector<std::string>& dialects) {
  for (const std::string& dialect : dialects) {
    for (const char* units : {"mm", "inch"}) {
      SCOPED_TRACE(path + " " + dialect + " " + units);
      json asked = request;
      asked["program"] = {{"dialect", dialect}, {"units", units}, {"name", "PART_7"}};
      const cutcalc::api::ApiResponse answer = endpoint.answer(asked);
      ASSERT_EQ(answer.status, 200) << answer.body;
      const json body = cutcalc::testing::parsed(answer);
      auto v = project_contract().check_response("POST", path, 200, answer.content_type, body);
      EXPECT_TRUE(v.empty()) << join(v);
      v = project_contract().check_response_headers("POST", path, 200, headers_of(answer));
      EXPECT_TRUE(v.empty()) << join(v);

      const cutcalc::api::ApiResponse text = endpoint.answer(asked, "text/plain");
      ASSERT_EQ(text.status, 200) << text.body;
      EXPECT_EQ(text.content_type, "text/plain; charset=us-ascii");
      EXPECT_EQ(text.body, body.at("program").get<std::string>());
      v = project_contract().check_response("POST", path, 200, text.content_type, text.body);
      EXPECT_TRUE(v.empty()) << join(v);
      const auto headers = headers_of(text);
      EXPECT_EQ(headers.count("Content-Disposition"), 1U);
      v = project_contract().check_response_headers("POST", path, 200, headers);
      EXPECT_TRUE(v.empty()) << join(v);
    }
  }
}

// What a lathe program answer's schema refuses, shown on real answers: `good` (without optional
// members) and `warned` (with a warning). Every member of `good` is required, none may be added,
// the dialect, units, decimals, file name and program are pinned, each warning has a documented
// code and a detail; the text/plain form is exactly the program under its exact media type.
void expect_lathe_answer_is_strict(const std::string& path, const json& good, const json& warned) {
  const std::string aj = "application/json";
  expect_valid_with_every_member_required(path, good);
  if (::testing::Test::HasFatalFailure()) return;
  json extra = good;
  extra["side_mm"] = 16.0;
  EXPECT_TRUE(
      names_pointer(project_contract().check_response("POST", path, 200, aj, extra), "/side_mm"));
  for (const auto& [key, bad] : std::vector<std::pair<std::string, json>>{
           {"dialect", "heidenhain"},
           {"units", "cm"},
           {"decimals", 2},
           {"decimals", 7},
           {"decimals", 4.5},
           {"file_name", "cutcalc.ngc"},
           {"file_name", "CUTCALC.nc"},
           {"program", "G21 G18 G90\nM30\n"},
           {"program", "%\n(CUTCALC POLYGON HOLE N4 D16.0000 A16.0000)\nM30\n%\n"}}) {
    json wrong = good;
    wrong[key] = bad;
    EXPECT_TRUE(
        names_pointer(project_contract().check_response("POST", path, 200, aj, wrong), "/" + key))
        << key << " " << bad.dump();
  }

  ASSERT_FALSE(warned.at("warnings").empty()) << warned.dump();
  EXPECT_TRUE(project_contract().check_response("POST", path, 200, aj, warned).empty())
      << join(project_contract().check_response("POST", path, 200, aj, warned));
  json bad_code = warned;
  bad_code["warnings"][0]["code"] = "phase_not_locked";  // the polygon hole's, not a lathe's
  EXPECT_TRUE(names_pointer(project_contract().check_response("POST", path, 200, aj, bad_code),
                            "/warnings/0/code"));
  json no_detail = warned;
  no_detail["warnings"][0].erase("detail");
  EXPECT_TRUE(names_pointer(project_contract().check_response("POST", path, 200, aj, no_detail),
                            "/warnings/0/detail"));

  const std::string text = "text/plain; charset=us-ascii";
  const std::string program = good.at("program").get<std::string>();
  EXPECT_TRUE(project_contract().check_response("POST", path, 200, text, program).empty());
  EXPECT_TRUE(project_contract()
                  .check_response("POST", path, 200, "text/plain; charset=US-ASCII", program)
                  .empty());
  EXPECT_FALSE(project_contract().check_response("POST", path, 200, "text/plain", program).empty());
  EXPECT_FALSE(project_contract()
                   .check_response("POST", path, 200, "text/plain; charset=utf-8", program)
                   .empty());
  EXPECT_FALSE(project_contract().check_response("POST", path, 200, text, good).empty());
  EXPECT_FALSE(project_contract().check_response("POST", path, 200, text, "M30\n").empty());
  EXPECT_FALSE(project_contract().check_response("POST", path, 200, aj, program).empty());

  // Content-Disposition: optional (absent with JSON), the dialect's file name in capitals.
  EXPECT_TRUE(project_contract()
                  .check_response_headers("POST", path, 200, {{"X-Request-Id", "abc"}})
                  .empty());
  for (const char* bad : {R"(attachment; filename="cutcalc.ngc")",
                          R"(inline; filename="CUTCALC.ngc")", R"(attachment; filename="CUTCALC")",
                          R"(attachment; filename="polygon-hole-N4-d16.0000.ngc")"}) {
    EXPECT_EQ(project_contract()
                  .check_response_headers("POST", path, 200,
                                          {{"X-Request-Id", "abc"}, {"Content-Disposition", bad}})
                  .size(),
              1U)
        << bad;
  }
}

// A real refusal (422 problem+json, whatever Accept asked for) conforms; every error status is
// documented as problem+json alone.
void expect_real_refusal_conforms(const std::string& path, const EndpointProbe& endpoint,
                                  const json& bad_request) {
  const std::string pj = "application/problem+json";
  for (const char* accept : {"application/json", "text/plain"}) {
    const cutcalc::api::ApiResponse refusal = endpoint.answer(bad_request, accept);
    ASSERT_EQ(refusal.status, 422) << refusal.body;
    EXPECT_EQ(refusal.content_type.rfind(pj, 0), 0U) << refusal.content_type;
    const auto v = project_contract().check_response("POST", path, 422, refusal.content_type,
                                                     cutcalc::testing::parsed(refusal));
    EXPECT_TRUE(v.empty()) << accept << join(v);
  }
  for (const int status : {400, 405, 413, 415, 422, 500, 503}) {
    const json& response = deref(doc()["paths"][path]["post"]["responses"][std::to_string(status)]);
    EXPECT_TRUE(response["content"].contains(pj)) << status;
    EXPECT_EQ(response["content"].size(), 1U) << status;
  }
}

TEST(OpenApiDocument, LatheFlatAnswersJsonOrThePlainProgram) {
  const std::string path = cutcalc::testing::kLatheFlatPath;
  expect_real_answers_conform(path, kLatheFlat, lathe_flat_request(), {"linuxcnc", "sinumerik"});

  const json good = cutcalc::testing::parsed(kLatheFlat.answer(lathe_flat_request()));
  json warned_request = lathe_flat_request();
  warned_request["feed_mm_per_min"] = 20000;
  warned_request["flatness_tolerance_mm"] = 0.002;
  const json warned = cutcalc::testing::parsed(kLatheFlat.answer(warned_request));
  expect_lathe_answer_is_strict(path, good, warned);

  // Fanuc is no lathe-flat dialect (no C-axis flats there); a step row has all its members.
  const std::string aj = "application/json";
  json fanuc = good;
  fanuc["dialect"] = "fanuc";
  fanuc["file_name"] = "O0001.nc";
  const auto v = project_contract().check_response("POST", path, 200, aj, fanuc);
  EXPECT_TRUE(names_pointer(v, "/dialect")) << join(v);
  EXPECT_TRUE(names_pointer(v, "/file_name")) << join(v);
  json row = good;
  row["steps_table"][0].erase("chord_mm");
  EXPECT_TRUE(names_pointer(project_contract().check_response("POST", path, 200, aj, row),
                            "/steps_table/0"));
  json steps = good;
  steps["steps"] = 1001;
  EXPECT_TRUE(
      names_pointer(project_contract().check_response("POST", path, 200, aj, steps), "/steps"));

  json bad_request = lathe_flat_request();
  bad_request["part_diameter_mm"] = 0;
  expect_real_refusal_conforms(path, kLatheFlat, bad_request);
}

TEST(OpenApiDocument, GroovingCycleAnswersJsonOrThePlainProgram) {
  const std::string path = cutcalc::testing::kGroovingCyclePath;
  expect_real_answers_conform(path, kGroovingCycle, grooving_cycle_request(),
                              {"linuxcnc", "fanuc", "sinumerik"});

  const json good = cutcalc::testing::parsed(kGroovingCycle.answer(grooving_cycle_request()));
  // Fanuc G97 at 150.5 rpm over a 140 rpm limit, X2 0.6, N = 2 (several warnings).
  json warned_request = grooving_cycle_request();
  warned_request.erase("cutting_speed_m_per_min");
  warned_request["spindle_speed_rpm"] = 150.5;
  warned_request["max_spindle_rpm"] = 140;
  warned_request["shift_mm"] = 0.6;
  warned_request["groove_depth_mm"] = 0.24;
  warned_request["program"] = {{"dialect", "fanuc"}};
  const json warned = cutcalc::testing::parsed(kGroovingCycle.answer(warned_request));
  expect_lathe_answer_is_strict(path, good, warned);

  const std::string aj = "application/json";
  for (const auto& [key, bad] :
       std::vector<std::pair<std::string, json>>{{"end_side", "middle"},
                                                 {"wall_rz_branch", "plunge"},
                                                 {"revolutions", 0},
                                                 {"revolutions", 20001},
                                                 {"shift_revolutions", -1},
                                                 {"wall_rz_um", -0.1}}) {
    json wrong = good;
    wrong[key] = bad;
    EXPECT_TRUE(
        names_pointer(project_contract().check_response("POST", path, 200, aj, wrong), "/" + key))
        << key << " " << bad.dump();
  }

  json bad_request = grooving_cycle_request();
  bad_request.erase("nose_radius_mm");
  expect_real_refusal_conforms(path, kGroovingCycle, bad_request);
}

#ifdef CUTCALC_REFERENCE_DIR
// Every reference request with an expected 200 satisfies the request schema and its expected body
// the response schema (complete in these files except polygon-hole.json, whose answer is assembled
// from its expectations by complete_polygon_body). A 422 case fails the request schema at the
// expected pointer, unless its 422 comes from a check that JSON Schema cannot state (a geometric
// or model check, or a relation between two values): those cases are listed and must pass it.
TEST(OpenApiDocument, ReferenceCasesSatisfyTheContract) {
  const std::set<std::string> model_checks = {
      // resultant-speeds: no engagement arc, a contact angle beyond rho_e.
      "rs-err-no-contact",
      "rs-err-angle-outside-arc",
      // bore-milling: r >= R, pitch angle >= 180 deg.
      "bm-err-r-equals-R",
      "bm-err-pitch-180",
  };
  int checked = 0;
  int rejected_by_schema = 0;
  std::set<std::string> model_checks_seen;
  for (const auto& [file, path] : std::map<std::string, std::string>{
           {"entry-length.json", "/v1/entry-length"},
           {"main-time.json", "/v1/main-time"},
           {"resultant-speeds.json", "/v1/resultant-speeds"},
           {"roughness-groove-wall.json", "/v1/roughness/groove-wall"},
           {"roughness-bore-milling.json", "/v1/roughness/bore-milling"},
           {"polygon-hole.json", "/v1/polygon-hole/gcode"}}) {
    std::ifstream in(std::string(CUTCALC_REFERENCE_DIR) + "/" + file);
    ASSERT_TRUE(in) << file;
    const json cases = json::parse(in);
    EXPECT_EQ(cases.value("endpoint", path), path) << file;
    const bool new_file = file != "entry-length.json" && file != "main-time.json";
    for (const auto& c : cases["cases"]) {
      const std::string id = c["id"].get<std::string>();
      const auto request_violations = project_contract().check_request("POST", path, c["request"]);
      if (c["expect"]["status"] == 200) {
        EXPECT_TRUE(request_violations.empty()) << file << " " << id << join(request_violations);
        json body = file == "polygon-hole.json" ? complete_polygon_body(c) : c["expect"]["body"];
        if (file == "roughness-groove-wall.json") {
          // The file predates `ra_um` (roughness.md R.7, always in the answer; its values are in
          // next/roughness-groove-wall.json): any valid value completes the body.
          body["ra_um"] = 0.0;
        }
        const auto v =
            project_contract().check_response("POST", path, 200, "application/json", body);
        EXPECT_TRUE(v.empty()) << file << " " << id << join(v);
      } else {
        EXPECT_EQ(c["expect"]["status"], 422) << file << " " << id;
        const std::string pointer = c["expect"]["pointer"].get<std::string>();
        if (!request_violations.empty()) {
          ++rejected_by_schema;
          EXPECT_TRUE(names_pointer(request_violations, pointer))
              << file << " " << id << " expected " << pointer << join(request_violations);
        }
        if (model_checks.count(id) != 0) {
          model_checks_seen.insert(id);
          EXPECT_TRUE(request_violations.empty())
              << file << " " << id << " is listed as a model check" << join(request_violations);
        } else if (new_file) {
          EXPECT_FALSE(request_violations.empty()) << file << " " << id << " (expected 422 at \""
                                                   << pointer << "\") passes the request schema";
        }
      }
      ++checked;
    }
  }
  EXPECT_EQ(model_checks_seen, model_checks);
  EXPECT_GE(rejected_by_schema, 26);
  EXPECT_GE(checked, 108);
}
#endif

}  // namespace
