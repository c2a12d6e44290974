#include "support/request_schema.h"

#include "support/project_contract.h"

namespace cutcalc::testing {

using nlohmann::json;

const json& openapi_document() {
  static const json loaded = test_support::project_contract().document();
  return loaded;
}

const json& resolve_schema(const json& schema) {
  if (schema.is_object() && schema.contains("$ref")) {
    const std::string ref = schema.at("$ref").get<std::string>();
    return resolve_schema(openapi_document().at(json::json_pointer(ref.substr(1))));
  }
  return schema;
}

std::string schema_name_of(const json& schema_or_ref, std::string name) {
  const std::string prefix = "#/components/schemas/";
  const json* schema = &schema_or_ref;
  while (schema->is_object() && schema->contains("$ref")) {
    const std::string ref = schema->at("$ref").get<std::string>();
    if (ref.rfind(prefix, 0) == 0 && ref.find('/', prefix.size()) == std::string::npos) {
      name = ref.substr(prefix.size());
    }
    schema = &openapi_document().at(json::json_pointer(ref.substr(1)));
  }
  return name;
}

void walk_request_schema(const json& schema_or_ref, const json& instance,
                         const std::string& pointer, const std::string& name,
                         const std::function<void(const SchemaProperty&)>& visit) {
  const std::string schema_name = schema_name_of(schema_or_ref, name);
  const json& schema = resolve_schema(schema_or_ref);
  if (!schema.is_object()) return;
  for (const json& part : schema.value("allOf", json::array())) {
    walk_request_schema(part, instance, pointer, schema_name, visit);
  }
  for (const char* choice : {"oneOf", "anyOf"}) {
    for (const json& branch : schema.value(choice, json::array())) {
      if (fits_branch(resolve_schema(branch), instance)) {
        walk_request_schema(branch, instance, pointer, schema_name, visit);
        break;
      }
    }
  }
  if (instance.is_object() && schema.contains("properties")) {
    for (const auto& [key, property] : schema.at("properties").items()) {
      const std::string child = pointer + "/" + key;
      visit({child, schema_name + "." + key, property, resolve_schema(property),
             instance.contains(key)});
      if (instance.contains(key)) {
        walk_request_schema(property, instance.at(key), child, schema_name, visit);
      }
    }
  }
  if (instance.is_array() && schema.contains("items")) {
    for (std::size_t i = 0; i < instance.size(); ++i) {
      walk_request_schema(schema.at("items"), instance.at(i), pointer + "/" + std::to_string(i),
                          schema_name, visit);
    }
  }
}

void visit_declared_properties(const json& schema_or_ref, const std::string& name,
                               std::set<std::string>& seen_schemas,
                               const std::function<void(const SchemaProperty&)>& visit) {
  const std::string schema_name = schema_name_of(schema_or_ref, name);
  if (schema_or_ref.is_object() && schema_or_ref.contains("$ref") &&
      !seen_schemas.insert(schema_name).second) {
    return;
  }
  const json& schema = resolve_schema(schema_or_ref);
  if (!schema.is_object()) return;
  for (const char* list : {"allOf", "oneOf", "anyOf"}) {
    for (const json& part : schema.value(list, json::array())) {
      visit_declared_properties(part, schema_name, seen_schemas, visit);
    }
  }
  const json properties = schema.value("properties", json::object());  // named: items() views it
  for (const auto& [key, property] : properties.items()) {
    visit({"", schema_name + "." + key, property, resolve_schema(property), false});
    visit_declared_properties(property, schema_name, seen_schemas, visit);
  }
  if (schema.contains("items")) {
    visit_declared_properties(schema.at("items"), schema_name, seen_schemas, visit);
  }
}

bool fits_branch(const json& branch, const json& instance) {
  if (!instance.is_object() || !branch.contains("properties")) return false;
  const json& properties = branch.at("properties");
  for (const auto& [key, property] : properties.items()) {
    const json& sub = resolve_schema(property);
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

const json& request_body(const std::string& path) {
  return openapi_document()
      .at("paths")
      .at(path)
      .at("post")
      .at("requestBody")
      .at("content")
      .at("application/json");
}

}  // namespace cutcalc::testing
