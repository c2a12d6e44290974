// The calculation route table (api/routes.h) against openapi.yaml, the reference files and the
// web page: a route that lacks any of them, or an openapi calculation path without a route, fails
// here. The fuzzers, their seeds and the browser tests iterate the same table, so a route has its
// fuzz harness by being in it.

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "api/route_table_json.h"
#include "api/routes.h"
#include "support/project_contract.h"
#include "support/route_table_check.h"

#ifndef CUTCALC_REFERENCE_DIR
#error "CUTCALC_REFERENCE_DIR must be defined"
#endif
#ifndef CUTCALC_WEB_DIR
#error "CUTCALC_WEB_DIR must be defined"
#endif

namespace cutcalc {
namespace {

using nlohmann::json;
using test_support::RouteTableInputs;

std::string index_html() {
  std::ifstream in(std::string(CUTCALC_WEB_DIR) + "/index.html");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

RouteTableInputs project_inputs(std::span<const api::CalculationRoute> routes) {
  return {routes, test_support::project_contract().document(), CUTCALC_REFERENCE_DIR, index_html()};
}

std::string joined(const std::vector<std::string>& problems) {
  std::string text;
  for (const std::string& problem : problems) {
    text += "\n  " + problem;
  }
  return text;
}

bool mentions(const std::vector<std::string>& problems, const std::string& words) {
  return std::any_of(problems.begin(), problems.end(), [&](const std::string& problem) {
    return problem.find(words) != std::string::npos;
  });
}

TEST(RouteTable, EveryRouteHasItsOpenApiPathReferenceFilesPlotFieldAndPageSection) {
  const auto problems =
      test_support::route_table_problems(project_inputs(api::calculation_routes()));
  EXPECT_TRUE(problems.empty()) << joined(problems);
}

TEST(RouteTable, ARouteLackingItsPathReferenceFileOrPageIsNamed) {
  const std::array routes = {
      api::CalculationRoute{.path = "/v1/thread-milling",
                            .handler = nullptr,
                            .forms = api::AnswerForms::json_and_plain_text_program,
                            .plot = {"include_profile", "true", ""},
                            .reference_files = {"thread-milling.json"},
                            .page_section = "thread"}};
  const auto problems = test_support::route_table_problems(project_inputs(routes));
  EXPECT_TRUE(mentions(problems, "/v1/thread-milling: no POST /v1/thread-milling in openapi.yaml"))
      << joined(problems);
  EXPECT_TRUE(mentions(problems, "thread-milling.json does not exist")) << joined(problems);
  EXPECT_TRUE(mentions(problems, "no <section id=\"thread\">")) << joined(problems);
  EXPECT_TRUE(mentions(problems, "no nav link to #thread")) << joined(problems);
}

// The page imports each section's module (web/ui/app.js); the row names it.
TEST(RouteTable, EveryPageSectionNamesItsModule) {
  const std::filesystem::path ui = std::filesystem::path(CUTCALC_WEB_DIR) / "ui";
  std::ifstream app_file(ui / "app.js");
  const std::string app((std::istreambuf_iterator<char>(app_file)),
                        std::istreambuf_iterator<char>());
  ASSERT_FALSE(app.empty());
  for (const api::CalculationRoute& route : api::calculation_routes()) {
    if (route.page_section == api::kNoPage) {
      EXPECT_TRUE(route.page_module.empty()) << route.path;
      continue;
    }
    ASSERT_TRUE(route.page_module.ends_with(".js")) << route.path;
    const std::filesystem::path module = ui / route.page_module;
    EXPECT_TRUE(std::filesystem::is_regular_file(module)) << route.path << ": " << module;
    EXPECT_NE(app.find("from './" + std::string(route.page_module) + "';"), std::string::npos)
        << "web/ui/app.js does not import " << route.page_module;
  }
}

TEST(RouteTable, AProgramWriterThatIsNotHeavyIsNamed) {
  const std::array routes = {
      api::CalculationRoute{.path = "/v1/grooving/cycle",
                            .handler = nullptr,
                            .forms = api::AnswerForms::json_and_plain_text_program,
                            .reference_files = {"next/grooving-cycle.json"}}};
  const auto problems = test_support::route_table_problems(project_inputs(routes));
  EXPECT_TRUE(mentions(problems, "/v1/grooving/cycle: writes a program but is not heavy"))
      << joined(problems);
}

TEST(RouteTable, AnOpenApiCalculationPathWithoutARouteIsNamed) {
  RouteTableInputs inputs = project_inputs(api::calculation_routes());
  inputs.openapi["paths"]["/v1/thread-milling"] = inputs.openapi["paths"]["/v1/main-time"];
  const auto problems = test_support::route_table_problems(inputs);
  EXPECT_TRUE(mentions(problems, "/v1/thread-milling: in openapi.yaml, not in the route table"))
      << joined(problems);
  EXPECT_EQ(problems.size(), 1U) << joined(problems);
}

TEST(RouteTable, WrongFormsPlotFieldAndReferenceFilesAreNamed) {
  std::array routes = {api::CalculationRoute{.path = "/v1/main-time",
                                             .handler = nullptr,
                                             .forms = api::AnswerForms::json_and_plain_text_program,
                                             .plot = {"include_scheme", "true", ""},
                                             .reference_files = {"entry-length.json"},
                                             .page_section = api::kNoPage}};
  const auto problems = test_support::route_table_problems(project_inputs(routes));
  EXPECT_TRUE(mentions(problems, "answers a text/plain program, openapi.yaml lists none"))
      << joined(problems);
  EXPECT_TRUE(mentions(problems, "its plot member include_scheme is not in the request schema"))
      << joined(problems);
  EXPECT_TRUE(mentions(problems, "entry-length.json checks /v1/entry-length")) << joined(problems);
  EXPECT_TRUE(mentions(problems, "the reference file main-time.json is not listed"))
      << joined(problems);
  EXPECT_FALSE(mentions(problems, "section")) << "kNoPage asks for no page" << joined(problems);
}

// The next/ mechanism: a listed next/ file joins the files every consumer replays, and only a
// listed one does.
TEST(RouteTable, ReplayedReferenceFilesAreTheDirectoryAndTheListedNextFiles) {
  const auto today =
      test_support::replayed_reference_files(CUTCALC_REFERENCE_DIR, api::calculation_routes());
  std::set<std::string> listed_next;
  for (const api::CalculationRoute& route : api::calculation_routes()) {
    for (const std::string_view file : api::reference_files_of(route)) {
      if (file.starts_with("next/")) {
        listed_next.emplace(file);
      }
    }
  }
  std::set<std::string> replayed_next;
  std::copy_if(today.begin(), today.end(), std::inserter(replayed_next, replayed_next.end()),
               [](const std::string& file) { return file.starts_with("next/"); });
  EXPECT_EQ(replayed_next, listed_next);
  EXPECT_TRUE(std::find(today.begin(), today.end(), "main-time.json") != today.end());

  const std::array listed = {
      api::CalculationRoute{.path = "/v1/main-time",
                            .handler = nullptr,
                            .reference_files = {"main-time.json", "next/main-time.json"}}};
  const auto with_next = test_support::replayed_reference_files(CUTCALC_REFERENCE_DIR, listed);
  EXPECT_EQ(with_next.size(), today.size() - replayed_next.size() + 1);
  EXPECT_TRUE(std::find(with_next.begin(), with_next.end(), "next/main-time.json") !=
              with_next.end());
  // ... and a listed next/ file passes the table check once it exists and names the endpoint.
  const auto problems = test_support::route_table_problems(project_inputs(listed));
  EXPECT_FALSE(mentions(problems, "next/main-time.json")) << joined(problems);
}

TEST(RouteTable, PrintedAsJsonWithEveryField) {
  const json rows = api::calculation_routes_json();
  ASSERT_EQ(rows.size(), api::calculation_routes().size());
  const json& polygon = *std::find_if(rows.begin(), rows.end(), [](const json& row) {
    return row["path"] == "/v1/polygon-hole/gcode";
  });
  EXPECT_EQ(polygon["slug"], "polygon_hole_gcode");
  EXPECT_EQ(polygon["forms"], json({"json", "plain_text"}));
  EXPECT_EQ(polygon["plot_field"]["name"], "include_geometry");
  EXPECT_EQ(polygon["plot_field"]["example"], true);
  EXPECT_EQ(polygon["reference_files"], json({"polygon-hole.json", "next/polygon-hole.json"}));
  EXPECT_EQ(polygon["next_reference_files"], json({"next/polygon-hole.json"}));
  EXPECT_EQ(polygon["page_section"], "polygon");
  EXPECT_EQ(polygon["page_module"], "sections/polygon_hole.js");
  EXPECT_EQ(polygon["heavy"], true);
  const json& main_time = rows[1];
  EXPECT_EQ(main_time["plot_field"], nullptr);
  EXPECT_EQ(main_time["forms"], json({"json"}));
  EXPECT_EQ(main_time["heavy"], false);
}

}  // namespace
}  // namespace cutcalc
