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
#include "support/request_schema.h"
#include "support/route_table_check.h"
#include "support/test_server.h"

#ifndef CUTCALC_REFERENCE_DIR
#error "CUTCALC_REFERENCE_DIR must be defined"
#endif

namespace cutcalc::testing {
namespace {

using nlohmann::json;

struct Insertion {
  std::string pointer;  // where the default goes
  json value;
  std::string origin;    // the schema property that declares it: "EntryLengthRequest.approach_mm"
  bool present = false;  // the request gives the field: compare it removed with it set to default
};

void collect(const json& schema_or_ref, const json& instance, const std::string& pointer,
             const std::string& name, std::vector<Insertion>& out) {
  walk_request_schema(schema_or_ref, instance, pointer, name, [&out](const SchemaProperty& field) {
    const json& with_default = field.property.contains("default") ? field.property : field.resolved;
    if (with_default.contains("default")) {
      out.push_back({field.pointer, with_default.at("default"), field.origin, field.present});
    }
  });
}

// Every default declared anywhere under a request schema, as "Schema.property".
void declared_defaults(const json& schema_or_ref, const std::string& name,
                       std::set<std::string>& seen_schemas, std::set<std::string>& out) {
  visit_declared_properties(schema_or_ref, name, seen_schemas, [&out](const SchemaProperty& field) {
    if (field.property.contains("default") || field.resolved.contains("default")) {
      out.insert(field.origin);
    }
  });
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
    const json& body = request_body(path);
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

// A client (or a validator with useDefaults) fills in every default at once, not one at a time:
// declared defaults must be sendable together (two exclusive fields that both declared a default
// made every such request a 422).
TEST(SchemaDefaults, AllDefaultsSentTogetherGiveTheAnswerOfOmittingThem) {
  int comparisons = 0;
  for (const std::string& file :
       test_support::replayed_reference_files(CUTCALC_REFERENCE_DIR, api::calculation_routes())) {
    const json reference = load_reference(file);
    const std::string path = reference.at("endpoint").get<std::string>();
    const json& body = request_body(path);
    for (const auto& [name, request] : base_requests(reference, body)) {
      std::vector<Insertion> insertions;
      collect(body.at("schema"), request, "", "", insertions);
      json filled = request;
      for (const Insertion& insertion : insertions) {
        if (!insertion.present) filled[json::json_pointer(insertion.pointer)] = insertion.value;
      }
      if (filled == request) continue;
      const JsonReply omitted = post(path, request.dump());
      const JsonReply sent = post(path, filled.dump());
      ASSERT_EQ(omitted.status, 200) << path << " " << name << ": " << omitted.body.substr(0, 300);
      EXPECT_EQ(sent.status, 200) << "every default sent in " << name << " (" << filled.dump()
                                  << "): " << sent.body.substr(0, 300);
      EXPECT_EQ(sent.body, omitted.body) << "every default sent changes the answer of " << name;
      ++comparisons;
    }
  }
  EXPECT_GT(comparisons, 20);
}

}  // namespace
}  // namespace cutcalc::testing
