#pragma once
// openapi.yaml's request schemas walked alongside a request: what the schema tests (defaults,
// bounds) share.

#include <functional>
#include <set>
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

// The name of the component schema a (chain of) reference(s) ends in, else `name`.
std::string schema_name_of(const nlohmann::json& schema_or_ref, std::string name);

// A property of an object schema, met while walking a request alongside its schema.
struct SchemaProperty {
  std::string pointer;             // the field in the request
  std::string origin;              // "EntryLengthRequest.approach_mm": where it is declared
  const nlohmann::json& property;  // as written (a $ref may have siblings such as default)
  const nlohmann::json& resolved;  // its schema, references resolved
  bool present;                    // the request gives the field
};

// Walks `schema_or_ref` alongside `instance` (at `pointer`, in the schema named `name`): the
// allOf parts, the oneOf/anyOf branch the instance fits, every property an object declares
// (given or not), then the given members and array items in turn.
void walk_request_schema(const nlohmann::json& schema_or_ref, const nlohmann::json& instance,
                         const std::string& pointer, const std::string& name,
                         const std::function<void(const SchemaProperty&)>& visit);

// Every property declared anywhere under `schema_or_ref` (given or not, every branch), once per
// component schema (`seen_schemas` holds the names visited): what a test must be able to exercise.
void visit_declared_properties(const nlohmann::json& schema_or_ref, const std::string& name,
                               std::set<std::string>& seen_schemas,
                               const std::function<void(const SchemaProperty&)>& visit);

// The request body description (schema, examples) of POST `path`.
const nlohmann::json& request_body(const std::string& path);

}  // namespace cutcalc::testing
