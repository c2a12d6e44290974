#pragma once
// This repository's openapi.yaml as a contract checker, loaded once per test binary.

#include <string>

#include <nlohmann/json.hpp>

#include "support/openapi_contract.h"
#include "support/test_server.h"

namespace cutcalc::test_support {

const OpenApiContract& project_contract();

}  // namespace cutcalc::test_support

namespace cutcalc::testing {

// POSTs `request` to the test server and expects a 200 (its answer is checked against openapi.yaml
// with every other logged exchange, support/exchange_log.h).
JsonReply post_ok(const std::string& path, const nlohmann::json& request);

// Fails the running test, here and now, for each way the answer to a POST to `path` breaks
// openapi.yaml (the logged exchanges are checked again after all tests).
void expect_conforms(const std::string& path, const JsonReply& reply);

}  // namespace cutcalc::testing
