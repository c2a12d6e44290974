#pragma once
// What the acceptance tests of the lathe programs (grooving cycle, lathe flat) share: the reference
// cases that answer 200, a reference request with other program options, the program written by
// the endpoint's handler (the same path as HTTP), checked against the dialect's text rules,
// translated to LinuxCNC and run through rs274 with tools 1-99, and rs274's canonical calls.

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "api/json_endpoint.h"

namespace cutcalc::test::gcode {

// One canonical call of rs274's output: STRAIGHT_TRAVERSE, STRAIGHT_FEED, SET_FEED_RATE,
// SET_FEED_MODE or DWELL, with its arguments.
struct CanonCall {
  std::string name;
  std::vector<double> args;
};
std::vector<CanonCall> canon_calls(const std::string& output);

// The cases of a reference file ("next/grooving-cycle.json") that answer 200.
std::vector<nlohmann::json> ok_reference_cases(const std::string& file);

// The request of `reference` with its program options set to `dialect` and `units` (members that
// only another dialect takes are dropped) and, when given, `decimals`.
nlohmann::json request_with_program(const nlohmann::json& reference, const std::string& dialect,
                                    const std::string& units, std::optional<int> decimals);

struct LatheRun {
  nlohmann::json body;   // the JSON answer
  std::string linuxcnc;  // the program translated to LinuxCNC
  std::vector<CanonCall> canon;
  bool ok = false;  // rs274 ran and accepted it
};
// Writes the program of `request` with `handler`, expects the dialect's text rules and rs274's
// acceptance after the translation.
LatheRun write_and_run(api::JsonHandler handler, const nlohmann::json& request,
                       const std::string& dialect);

// Expects `other` to make the same canonical calls as `reference`, argument by argument within
// `tolerance` (another dialect's program of the same request, translated).
void expect_same_motion(const LatheRun& reference, const LatheRun& other, double tolerance);

}  // namespace cutcalc::test::gcode
