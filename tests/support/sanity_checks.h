#pragma once
// Checks every calculation answer must pass, whatever the input: 200 or 422 only, no NaN or
// infinity, no negative length, and conformance to openapi.yaml.

#include <string>

#include <nlohmann/json.hpp>

#include "api/json_endpoint.h"

namespace cutcalc::testing {

// Runs `request` through the endpoint's handler pipeline (no server) and checks the answer with
// gtest assertions. Returns the status (0 when a fatal check failed).
int expect_sane_answer(const char* path, api::JsonHandler handler, const nlohmann::json& request);

}  // namespace cutcalc::testing
