// A minimum, maximum, exclusive bound or list length in openapi.yaml's request schemas is a promise
// to generated clients and validators that the server draws the line at the same place. Every
// bound is tried in a reference request (or a documented example): the field set to the last valid
// value must draw no range error at its pointer, one step past it (the next double, or the next
// integer, or one list element more or fewer) must be a 422 with a range error at that pointer.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>
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

constexpr std::array kBoundKeywords = {"minimum",          "maximum",  "exclusiveMinimum",
                                       "exclusiveMaximum", "minItems", "maxItems"};

// The codes of a field's own range rules (the others at a pointer are rules between fields or of
// the model, which a valid value may still meet).
bool is_range_error(const json& error) {
  static const std::set<std::string> codes = {"must_be_positive", "must_not_be_negative",
                                              "below_resolution", "out_of_range",
                                              "wrong_list_length"};
  return codes.count(error.value("code", "")) == 1;
}

struct Site {
  std::string pointer;  // the field in the request
  json bounds;          // keyword -> value, from the property and its resolved schema
  bool integer = false;
  bool present = false;  // the request gives the field
  std::string origin;    // "EntryLengthRequest.approach_mm"
};

void collect(const json& schema_or_ref, const json& instance, const std::string& pointer,
             const std::string& name, std::vector<Site>& out) {
  walk_request_schema(schema_or_ref, instance, pointer, name, [&out](const SchemaProperty& field) {
    Site site{field.pointer, json::object(), field.resolved.value("type", "") == "integer",
              field.present, field.origin};
    for (const json* source : {&field.resolved, &field.property}) {
      for (const char* keyword : kBoundKeywords) {
        if (source->contains(keyword)) site.bounds[keyword] = source->at(keyword);
      }
    }
    if (!site.bounds.empty()) out.push_back(site);
  });
}

// `request` with one object read as another branch of its oneOf/anyOf: the branch's constant set,
// the fields it does not have dropped and a required number it adds copied from another field (a
// convex arc {R} as a concave one {R, B = R}), so that branches no reference request takes are
// tried too.
void branch_variants(const json& schema_or_ref, const json& instance, const std::string& pointer,
                     const json& request, std::vector<std::pair<std::string, json>>& out) {
  const json& schema = resolve_schema(schema_or_ref);
  if (!schema.is_object()) return;
  for (const json& part : schema.value("allOf", json::array())) {
    branch_variants(part, instance, pointer, request, out);
  }
  for (const char* choice : {"oneOf", "anyOf"}) {
    for (const json& branch_ref : schema.value(choice, json::array())) {
      const json& branch = resolve_schema(branch_ref);
      if (!instance.is_object() || fits_branch(branch, instance)) continue;
      const json properties = branch.value("properties", json::object());  // items() views it
      for (const auto& [key, property] : properties.items()) {
        const json& sub = resolve_schema(property);
        if (!sub.contains("const") || !instance.contains(key)) continue;
        json variant = json::object();
        json number;  // a number of the instance, for a required number the branch adds
        for (const auto& [name, value] : instance.items()) {
          if (properties.contains(name)) variant[name] = value;
          if (value.is_number() && number.is_null()) number = value;
        }
        variant[key] = sub.at("const");
        for (const json& required : branch.value("required", json::array())) {
          const std::string name = required.get<std::string>();
          if (!variant.contains(name) && !number.is_null() &&
              resolve_schema(properties.at(name)).value("type", "") == "number") {
            variant[name] = number;
          }
        }
        if (!fits_branch(branch, variant)) continue;
        json whole = request;
        whole[json::json_pointer(pointer)] = variant;
        out.emplace_back(pointer + " as " + variant.dump(), whole);
      }
    }
  }
  if (instance.is_object() && schema.contains("properties")) {
    for (const auto& [key, property] : schema.at("properties").items()) {
      if (instance.contains(key)) {
        branch_variants(property, instance.at(key), pointer + "/" + key, request, out);
      }
    }
  }
}

// Every bound declared anywhere under a request schema, as "Schema.property keyword".
void declared_bounds(const json& schema_or_ref, const std::string& name,
                     std::set<std::string>& seen_schemas, std::set<std::string>& out) {
  visit_declared_properties(schema_or_ref, name, seen_schemas, [&out](const SchemaProperty& field) {
    for (const char* keyword : kBoundKeywords) {
      if (field.property.contains(keyword) || field.resolved.contains(keyword)) {
        out.insert(field.origin + " " + keyword);
      }
    }
  });
}

// The last valid value of a bound and the first invalid one.
std::pair<json, json> valid_and_invalid(const std::string& keyword, const json& bound,
                                        const json& current, bool integer) {
  if (keyword == "minItems" || keyword == "maxItems") {
    const auto length = bound.get<std::size_t>();
    const std::size_t invalid = keyword == "minItems" ? length - 1 : length + 1;
    const auto list = [&](std::size_t n) {
      json out = json::array();
      for (std::size_t i = 0; i < n; ++i) out.push_back(current.at(i % current.size()));
      return out;
    };
    return {list(length), list(invalid)};
  }
  const bool lower = keyword == "minimum" || keyword == "exclusiveMinimum";
  const bool exclusive = keyword == "exclusiveMinimum" || keyword == "exclusiveMaximum";
  if (integer) {
    const auto limit = bound.get<long long>();
    const long long outward = lower ? -1 : 1;
    return exclusive ? std::pair<json, json>{limit - outward, limit}
                     : std::pair<json, json>{limit, limit + outward};
  }
  const double limit = bound.get<double>();
  const double outward =
      lower ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
  return exclusive ? std::pair<json, json>{std::nextafter(limit, -outward), limit}
                   : std::pair<json, json>{limit, std::nextafter(limit, outward)};
}

std::vector<json> errors_at(const JsonReply& reply, const std::string& pointer) {
  std::vector<json> out;
  if (reply.status != 422 || !reply.json.is_object()) return out;
  for (const json& error : reply.json.value("errors", json::array())) {
    if (error.value("pointer", "") == pointer) out.push_back(error);
  }
  return out;
}

struct Candidate {
  std::string name;  // of the base request
  json request;
  Site site;
};

// Empty when the bound holds in `candidate`, else what went wrong.
std::string try_bound(const std::string& path, const std::string& keyword,
                      const Candidate& candidate) {
  const json::json_pointer pointer(candidate.site.pointer);
  const json current = candidate.request.value(pointer, json());
  if (keyword == "minItems" || keyword == "maxItems") {
    if (!current.is_array() || current.empty()) return "no list to lengthen in " + candidate.name;
  }
  const auto [valid, invalid] = valid_and_invalid(keyword, candidate.site.bounds.at(keyword),
                                                  current, candidate.site.integer);
  json at_bound = candidate.request;
  at_bound[pointer] = valid;
  json past_bound = candidate.request;
  past_bound[pointer] = invalid;
  // A field of one dialect only is tried in that dialect.
  for (const json& error : errors_at(post(path, past_bound.dump()), candidate.site.pointer)) {
    if (error.value("code", "") == "dialect_only" && error.contains("dialect")) {
      at_bound[pointer.parent_pointer() / "dialect"] = error.at("dialect");
      past_bound[pointer.parent_pointer() / "dialect"] = error.at("dialect");
    }
  }
  std::ostringstream problems;
  const JsonReply valid_reply = post(path, at_bound.dump());
  for (const json& error : errors_at(valid_reply, candidate.site.pointer)) {
    if (is_range_error(error)) {
      problems << "\n  " << (keyword.find("Items") == std::string::npos ? valid.dump() : "the list")
               << " (valid) refused: " << error.dump();
    }
  }
  const JsonReply invalid_reply = post(path, past_bound.dump());
  bool refused = false;
  for (const json& error : errors_at(invalid_reply, candidate.site.pointer)) {
    refused = refused || is_range_error(error);
  }
  if (!refused) {
    problems << "\n  " << (keyword.find("Items") == std::string::npos ? invalid.dump() : "the list")
             << " (invalid) gets " << invalid_reply.status << ": "
             << invalid_reply.body.substr(0, 300);
  }
  const std::string said = problems.str();
  return said.empty() ? ""
                      : candidate.name + (candidate.site.present ? "" : " (field added)") + said;
}

TEST(SchemaBounds, EveryBoundIsWhereTheServerDrawsTheLine) {
  // Being reworked elsewhere: the pass program's extra path must be 0 by a rule of the model.
  const std::set<std::string> skipped = {
      "/v1/main-time/program MainTimeProgramRequest.extra_path_mm"};
  std::set<std::string> declared;
  std::set<std::string> seen_schemas;
  // path, pointer, origin, keyword -> the requests it can be tried in (those giving the field
  // first)
  std::map<std::string, std::vector<Candidate>> candidates;
  std::map<std::string, std::pair<std::string, std::string>> what;  // key -> path, keyword
  // The reference files the replay sends: with the next/ files the route table lists.
  for (const std::string& file :
       test_support::replayed_reference_files(CUTCALC_REFERENCE_DIR, api::calculation_routes())) {
    const json reference = load_reference(file);
    const std::string path = reference.at("endpoint").get<std::string>();
    const json& body = request_body(path);
    declared_bounds(body.at("schema"), "", seen_schemas, declared);
    std::vector<std::pair<std::string, json>> bases = base_requests(reference, body);
    const std::size_t given = bases.size();
    for (std::size_t i = 0; i < given; ++i) {
      std::vector<std::pair<std::string, json>> variants;
      branch_variants(body.at("schema"), bases[i].second, "", bases[i].second, variants);
      for (auto& [change, variant] : variants) {
        bases.emplace_back(bases[i].first + " with " + change, std::move(variant));
      }
    }
    for (const auto& [name, request] : bases) {
      std::vector<Site> sites;
      collect(body.at("schema"), request, "", "", sites);
      for (const Site& site : sites) {
        for (const auto& [keyword, value] : site.bounds.items()) {
          const std::string key = path + " " + site.pointer + " " + site.origin + " " + keyword;
          auto& list = candidates[key];
          const Candidate candidate{name, request, site};
          if (site.present) {
            list.insert(std::find_if(list.begin(), list.end(),
                                     [](const Candidate& c) { return !c.site.present; }),
                        candidate);
          } else {
            list.push_back(candidate);
          }
          what[key] = {path, keyword};
        }
      }
    }
  }
  std::set<std::string> exercised;
  for (const auto& [key, list] : candidates) {
    const auto& [path, keyword] = what.at(key);
    const std::string origin = list.front().site.origin;
    if (skipped.count(path + " " + origin) == 1) {
      exercised.insert(origin + " " + keyword);
      continue;
    }
    std::string first_failure;
    bool holds = false;
    // The first request where the bound can be seen: a rule between fields may hide it in others.
    for (std::size_t i = 0; i < list.size() && i < 3 && !holds; ++i) {
      const std::string failure = try_bound(path, keyword, list[i]);
      holds = failure.empty();
      if (first_failure.empty()) first_failure = failure;
    }
    EXPECT_TRUE(holds) << key << " = " << list.front().site.bounds.at(keyword) << ": "
                       << first_failure;
    exercised.insert(origin + " " + keyword);
  }
  EXPECT_GT(exercised.size(), 50U);
  for (const std::string& bound : declared) {
    EXPECT_TRUE(exercised.count(bound) == 1)
        << bound << " is declared but no reference request or example reaches it";
  }
}

}  // namespace
}  // namespace cutcalc::testing
