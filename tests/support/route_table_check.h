#pragma once
// What the calculation route table (api/routes.h) must agree with: openapi.yaml, the reference
// files and the web page. One function, so that tests/api/route_table_test.cpp can also show it
// naming what a made-up route or document lacks.

#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "api/routes.h"

namespace cutcalc::test_support {

struct RouteTableInputs {
  std::span<const api::CalculationRoute> routes;
  nlohmann::json openapi;     // the document (OpenApiContract::document())
  std::string reference_dir;  // shared/reference
  std::string index_html;     // web/index.html
};

// Every disagreement, one sentence each; empty when the table is whole:
//  - a route without its POST path in openapi, or whose answer forms differ from the 200 media
//    types there (text/plain listed exactly for the program forms);
//  - a plot field that is not a member of the request schema;
//  - a route without a reference file, a listed file that does not exist or checks another
//    endpoint, a file of reference/*.json for the endpoint that the route does not list;
//  - a page section that is neither kNoPage nor a <section id> with a nav link in index.html;
//  - two routes with the same slug (the fuzz seed corpus and harness name);
//  - an openapi /v1/ path that is not a route.
std::vector<std::string> route_table_problems(const RouteTableInputs& inputs);

// The reference files every consumer replays: reference/*.json plus the next/ files the routes
// list, as paths relative to `reference_dir`, sorted.
std::vector<std::string> replayed_reference_files(const std::string& reference_dir,
                                                  std::span<const api::CalculationRoute> routes);

}  // namespace cutcalc::test_support
