// A `default` in openapi.yaml's request schemas is a promise to generated clients and validators
// (Ajv's useDefaults, openapi-typescript's defaults) that filling it in changes nothing. Every
// default is sent explicitly into every reference request that omits it, and the answer must be
// byte for byte the answer without it.

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "api/routes.h"
#include "support/project_contract.h"
#include "support/route_table_check.h"
#include "support/test_server.h"

#ifndef CUTCALC_REFERENCE_DIR
#error "CUTCALC_REFERENCE_DIR must be defined"
#endif

namespace cutcalc::testing {
namespace {

using nlohmann::json;

const json& document() {
  static const json loaded = test_support::project_contract().document();
  return loaded;
}

// A local "#/components/schemas/X" reference resolved (schemas here only use local ones).
const json& resolve(const json& schema) {
  if (schema.is_object() && schema.contains("$ref")) {
    const std::string ref = schema.at("$ref").get<std::string>();
    return resolve(document().at(json::json_pointer(ref.substr(1))));
  }
  return schema;
}

// Whether `instance` can be the object `branch` describes: its consts match, its required fields
// are there and, when the branch is closed, it has no other field.
bool fits(const json& branch, const json& instance) {
  if (!instance.is_object() || !branch.contains("properties")) return false;
  const json& properties = branch.at("properties");
  for (const auto& [key, property] : properties.items()) {
    const json& sub = resolve(property);
    if (sub.contains("const") && instance.contains(key) && instance.at(key) != sub.at("const")) {
      return false;
    }
  }
  for (const json& key : branch.value("required", json::array())) {
    if (!instance.contains(key.get<std::string>())) return false;
  }
  if (branch.value("additionalProperties", json(true)) == json(false)) {
    for (const auto& [key, value] : instance.items()) {
      if (!properties.contains(key)) return false;
    }
  }
  return true;
}

struct Insertion {
  std::string pointer;  // where the default goes
  json value;
  std::string origin;    // the schema property that declares it: "EntryLengthRequest.approach_mm"
  bool present = false;  // the request gives the field: compare it removed with it set to default
};

void collect(const json& schema_or_ref, const json& instance, const std::string& pointer,
             const std::string& name, std::vector<Insertion>& out) {
  std::string schema_name = name;
  if (schema_or_ref.is_object() && schema_or_ref.contains("$ref")) {
    const std::string ref = schema_or_ref.at("$ref").get<std::string>();
    schema_name = ref.substr(ref.rfind('/') + 1);
  }
  const json& schema = resolve(schema_or_ref);
  if (!schema.is_object()) return;
  for (const json& part : schema.value("allOf", json::array())) {
    collect(part, instance, pointer, schema_name, out);
  }
  for (const char* choice : {"oneOf", "anyOf"}) {
    for (const json& branch : schema.value(choice, json::array())) {
      if (fits(resolve(branch), instance)) {
        collect(branch, instance, pointer, schema_name, out);
        break;
      }
    }
  }
  if (instance.is_object() && schema.contains("properties")) {
    for (const auto& [key, property] : schema.at("properties").items()) {
      const json& sub = resolve(property);
      const std::string child = pointer + "/" + key;
      const json& with_default = property.contains("default") ? property : sub;
      if (with_default.contains("default")) {
        out.push_back(
            {child, with_default.at("default"), schema_name + "." + key, instance.contains(key)});
      }
      if (instance.contains(key)) {
        collect(property, instance.at(key), child, schema_name, out);
      }
    }
  }
  if (instance.is_array() && schema.contains("items")) {
    for (std::size_t i = 0; i < instance.size(); ++i) {
      collect(schema.at("items"), instance.at(i), pointer + "/" + std::to_string(i), schema_name,
              out);
    }
  }
}

// Every default declared anywhere under a request schema, as "Schema.property".
void declared_defaults(const json& schema_or_ref, const std::string& name,
                       std::set<std::string>& seen_schemas, std::set<std::string>& out) {
  std::string schema_name = name;
  if (schema_or_ref.is_object() && schema_or_ref.contains("$ref")) {
    const std::string ref = schema_or_ref.at("$ref").get<std::string>();
    schema_name = ref.substr(ref.rfind('/') + 1);
    if (!seen_schemas.insert(schema_name).second) return;
  }
  const json& schema = resolve(schema_or_ref);
  if (!schema.is_object()) return;
  for (const char* list : {"allOf", "oneOf", "anyOf"}) {
    for (const json& part : schema.value(list, json::array())) {
      declared_defaults(part, schema_name, seen_schemas, out);
    }
  }
  const json properties = schema.value("properties", json::object());  // named: items() views it
  for (const auto& [key, property] : properties.items()) {
    if (property.contains("default") || resolve(property).contains("default")) {
      out.insert(schema_name + "." + key);
    }
    declared_defaults(property, schema_name, seen_schemas, out);
  }
  if (schema.contains("items"))
    declared_defaults(schema.at("items"), schema_name, seen_schemas, out);
}

// The requests every default is tried in: the reference cases answered 200 and the operation's
// documented request examples (the only ones with a polygon `program` object).
std::vector<std::pair<std::string, json>> base_requests(const json& reference,
                                                        const json& operation_body) {
  std::vector<std::pair<std::string, json>> bases;
  for (const json& item : reference.at("cases")) {
    if (item.at("expect").at("status") == 200) {
      bases.emplace_back(item.at("id").get<std::string>(), item.at("request"));
    }
  }
  const json examples = operation_body.value("examples", json::object());  // items() views it
  for (const auto& [name, example] : examples.items()) {
    bases.emplace_back("example " + name, example.at("value"));
  }
  return bases;
}

TEST(SchemaDefaults, EveryDefaultSentExplicitlyGivesTheAnswerOfOmittingIt) {
  std::set<std::string> exercised;
  std::set<std::string> declared;
  std::set<std::string> seen_schemas;
  int comparisons = 0;
  for (const std::string& file :
       test_support::replayed_reference_files(CUTCALC_REFERENCE_DIR, api::calculation_routes())) {
    const json reference = load_reference(file);
    const std::string path = reference.at("endpoint").get<std::string>();
    const json& body = document()
                           .at("paths")
                           .at(path)
                           .at("post")
                           .at("requestBody")
                           .at("content")
                           .at("application/json");
    const json& schema = body.at("schema");
    declared_defaults(schema, "", seen_schemas, declared);
    for (const auto& [name, request] : base_requests(reference, body)) {
      std::vector<Insertion> insertions;
      collect(schema, request, "", "", insertions);
      for (const Insertion& insertion : insertions) {
        json omitted_request = request;
        if (insertion.present) {
          omitted_request.at(json::json_pointer(insertion.pointer).parent_pointer())
              .erase(json::json_pointer(insertion.pointer).back());
        }
        json explicit_request = omitted_request;
        explicit_request[json::json_pointer(insertion.pointer)] = insertion.value;
        const JsonReply omitted = post(path, omitted_request.dump());
        // A given field removed may leave a request that another field's rule refuses (a fanuc
        // program_number without dialect fanuc): nothing to compare there.
        if (insertion.present && omitted.status != 200) continue;
        const JsonReply sent = post(path, explicit_request.dump());
        ASSERT_EQ(omitted.status, 200) << path << " " << name << " without " << insertion.origin
                                       << ": " << omitted.body.substr(0, 300);
        EXPECT_EQ(sent.status, 200) << insertion.origin << " = " << insertion.value << " sent in "
                                    << name << ": " << sent.body.substr(0, 300);
        EXPECT_EQ(sent.body, omitted.body)
            << insertion.origin << " = " << insertion.value << " changes the answer of " << name;
        exercised.insert(insertion.origin);
        ++comparisons;
      }
    }
  }
  EXPECT_GT(comparisons, 50);
  // Every declared default was tried at least once.
  for (const std::string& origin : declared) {
    EXPECT_TRUE(exercised.count(origin) == 1)
        << origin << " has a default that no reference request or example can exercise";
  }
}

}  // namespace
}  // namespace cutcalc::testing
