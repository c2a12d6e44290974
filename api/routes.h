#pragma once
// The calculation endpoints of API v1: one row each, and everything the rest of the project needs
// to know about an endpoint besides its own code. The service registers each as POST; the tests,
// the fuzzers, the reference replay and the browser tests iterate this table (the non-C++ ones
// read it as JSON: `cutcalc --routes`, api/route_table_json.h), and
// tests/api/route_table_test.cpp checks it against openapi.yaml, the reference files and the page.

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>

#include "api/json_endpoint.h"
#include "api/program/program_reader.h"

namespace cutcalc::api {

// The forms of a 200 answer, chosen by the Accept header.
enum class AnswerForms {
  json,                        // application/json only
  json_and_plain_text_program  // also text/plain: a G-code program
};

// The opt-in request member that adds plot data (a scheme, curve, geometry) to the answer.
struct PlotField {
  std::string_view name;      // empty: the endpoint has none
  std::string_view example;   // JSON text of a value that asks for the plot, e.g. "true", "91"
  std::string_view replaces;  // a member it cannot be combined with (dropped when it is set), or ""
};

// The page section of an endpoint that the web calculator does not offer.
inline constexpr std::string_view kNoPage = "-";

struct CalculationRoute {
  const char* path;
  JsonHandler handler;
  AnswerForms forms = AnswerForms::json;
  // With the text/plain form: what the program it writes holds (its endpoint states it).
  const program::ProgramPolicy* program = nullptr;
  // Its work can be heavy, so the service runs it on the calculation pool, off the event loops
  // that answer the light requests: an endpoint that writes a program does as much work as the
  // program has blocks (a request field decides: up to megabytes, tens of milliseconds), one that
  // times a program as much as the program it is sent.
  bool heavy = false;
  PlotField plot{};
  // Reference case files checking the endpoint, relative to shared/reference: "entry-length.json",
  // or "next/<name>.json" for a file of ../shared/reference/next/ (cases of calculations not built
  // before) once the endpoint serves what it checks; every consumer of reference files takes
  // reference/*.json plus the next/ files listed here. Unused slots stay empty.
  std::array<std::string_view, 3> reference_files{};
  std::string_view page_section = kNoPage;  // the id of its <section> in web/index.html
  // The section's module, relative to web/ui: "sections/grooving.js" ("" with kNoPage).
  std::string_view page_module = "";
  // The largest request body it takes; 0: the service's default (HttpLimits::max_body_bytes).
  std::size_t max_body_bytes = 0;
};

// The body limit of the endpoints that take a whole program (POST /v1/program-time).
inline constexpr std::size_t kProgramBodyBytes = 32 * 1024 * 1024;

std::span<const CalculationRoute> calculation_routes();

// The route of `path`, or nullptr.
const CalculationRoute* find_calculation_route(std::string_view path);

// The reference_files entries of `route` that are set.
std::span<const std::string_view> reference_files_of(const CalculationRoute& route);

// The path less /v1/ with '/' and '-' as '_': "/v1/roughness/groove-wall" -> roughness_groove_wall.
// It names the endpoint's fuzz seed corpus and harnesses (<slug>_fuzzer, <slug>_text_fuzzer).
std::string route_slug(std::string_view path);

}  // namespace cutcalc::api
