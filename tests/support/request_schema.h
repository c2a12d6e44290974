#pragma once
// openapi.yaml's request schemas walked alongside a request: what the schema tests (defaults,
// bounds) share.

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace cutcalc::testing {

// openapi.yaml as JSON, loaded once.
const nlohmann::json& openapi_document();

// A local "#/components/..." reference resolved (the document only uses local ones).
const nlohmann::json& resolve_schema(const nlohmann::json& schema);

// Whether `instance` can be the object `branch` describes: its consts match, its required fields
// are there and, when the branch is closed, it has no other field.
bool fits_branch(const nlohmann::json& branch, const nlohmann::json& instance);

// The requests a schema rule is tried in: the reference cases answered 200 and the operation's
// documented request examples (the only ones with a polygon `program` object), with their names.
std::vector<std::pair<std::string, nlohmann::json>> base_requests(
    const nlohmann::json& reference, const nlohmann::json& operation_body);

// The request body description (schema, examples) of POST `path`.
const nlohmann::json& request_body(const std::string& path);

}  // namespace cutcalc::testing
