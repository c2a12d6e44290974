#include "support/openapi_contract.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <regex>
#include <set>
#include <stdexcept>
#include <string_view>
#include <utility>

#include <yaml-cpp/yaml.h>

namespace cutcalc::test_support {
namespace {

using nlohmann::json;

// ------------------------------------------------------------------------------------------------
// YAML -> JSON, plain scalars typed by the YAML 1.2 core schema (what OpenAPI tools assume).

const std::regex& int_re() {
  static const std::regex re(R"([-+]?[0-9]+)");
  return re;
}
const std::regex& float_re() {
  static const std::regex re(R"([-+]?(\.[0-9]+|[0-9]+(\.[0-9]*)?)([eE][-+]?[0-9]+)?)");
  return re;
}

std::string_view strip_plus(std::string_view s) {
  return (!s.empty() && s.front() == '+') ? s.substr(1) : s;
}

json integer_scalar(std::string_view text, int base) {
  std::int64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value, base);
  if (ec == std::errc() && end == text.data() + text.size()) {
    return value;
  }
  double d = 0;  // out of range for int64: keep it as a number anyway
  std::from_chars(text.data(), text.data() + text.size(), d);
  return d;
}

json plain_scalar(const std::string& s) {
  if (s.empty() || s == "~" || s == "null" || s == "Null" || s == "NULL") {
    return nullptr;
  }
  if (s == "true" || s == "True" || s == "TRUE") {
    return true;
  }
  if (s == "false" || s == "False" || s == "FALSE") {
    return false;
  }
  if (std::regex_match(s, int_re())) {
    return integer_scalar(strip_plus(s), 10);
  }
  if (s.size() > 2 && s[0] == '0' && s[1] == 'o' &&
      s.find_first_not_of("01234567", 2) == std::string::npos) {
    return integer_scalar(std::string_view(s).substr(2), 8);
  }
  if (s.size() > 2 && s[0] == '0' && s[1] == 'x' &&
      s.find_first_not_of("0123456789abcdefABCDEF", 2) == std::string::npos) {
    return integer_scalar(std::string_view(s).substr(2), 16);
  }
  if (std::regex_match(s, float_re())) {
    const std::string_view text = strip_plus(s);
    double d = 0;
    std::from_chars(text.data(), text.data() + text.size(), d);
    return d;
  }
  if (s == ".inf" || s == ".Inf" || s == ".INF" || s == "+.inf" || s == "+.Inf" || s == "+.INF") {
    return HUGE_VAL;
  }
  if (s == "-.inf" || s == "-.Inf" || s == "-.INF") {
    return -HUGE_VAL;
  }
  if (s == ".nan" || s == ".NaN" || s == ".NAN") {
    return std::nan("");
  }
  return s;
}

json yaml_to_json(const YAML::Node& node, const std::string& where) {
  switch (node.Type()) {
    case YAML::NodeType::Null:
      return nullptr;
    case YAML::NodeType::Scalar: {
      const std::string& tag = node.Tag();
      if (tag == "!" || tag == "tag:yaml.org,2002:str") {
        return node.Scalar();  // quoted or block scalar
      }
      return plain_scalar(node.Scalar());
    }
    case YAML::NodeType::Sequence: {
      json out = json::array();
      std::size_t i = 0;
      for (const auto& item : node) {
        out.push_back(yaml_to_json(item, where + "/" + std::to_string(i++)));
      }
      return out;
    }
    case YAML::NodeType::Map: {
      json out = json::object();
      for (const auto& kv : node) {
        if (!kv.first.IsScalar()) {
          throw std::runtime_error("openapi: non-scalar mapping key at " + where);
        }
        const std::string key = kv.first.Scalar();
        if (out.contains(key)) {
          std::string message = "openapi: duplicate key '";
          message.append(key).append("' at ").append(where);
          throw std::runtime_error(message);
        }
        out[key] = yaml_to_json(kv.second, std::string(where).append("/").append(key));
      }
      return out;
    }
    case YAML::NodeType::Undefined:
      break;
  }
  throw std::runtime_error("openapi: undefined YAML node at " + where);
}

// ------------------------------------------------------------------------------------------------
// Small helpers.

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) {
    return "";
  }
  const auto e = s.find_last_not_of(" \t");
  return s.substr(b, e - b + 1);
}

std::string escape_token(const std::string& token) {
  std::string out;
  for (const char c : token) {
    if (c == '~') {
      out += "~0";
    } else if (c == '/') {
      out += "~1";
    } else {
      out += c;
    }
  }
  return out;
}

std::string child(const std::string& ptr, const std::string& token) {
  return ptr + "/" + escape_token(token);
}

void add(std::vector<std::string>& out, const std::string& ptr, const std::string& message) {
  out.push_back("at \"" + ptr + "\": " + message);
}

std::string type_name(const json& v) {
  switch (v.type()) {
    case json::value_t::null:
      return "null";
    case json::value_t::boolean:
      return "boolean";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
      return "integer";
    case json::value_t::number_float:
      return "number";
    case json::value_t::string:
      return "string";
    case json::value_t::array:
      return "array";
    case json::value_t::object:
      return "object";
    default:
      return "unknown";
  }
}

bool matches_type(const std::string& type, const json& v) {
  if (type == "null") {
    return v.is_null();
  }
  if (type == "boolean") {
    return v.is_boolean();
  }
  if (type == "object") {
    return v.is_object();
  }
  if (type == "array") {
    return v.is_array();
  }
  if (type == "string") {
    return v.is_string();
  }
  if (type == "number") {
    return v.is_number();
  }
  if (type == "integer") {
    if (v.is_number_integer()) {
      return true;  // also covers unsigned
    }
    if (!v.is_number_float()) {
      return false;
    }
    const double d = v.get<double>();
    return std::isfinite(d) && std::trunc(d) == d;
  }
  return false;
}

std::size_t utf8_length(const std::string& s) {
  std::size_t n = 0;
  for (const char c : s) {
    if ((static_cast<unsigned char>(c) & 0xC0U) != 0x80U) {
      ++n;
    }
  }
  return n;
}

std::string schema_label(const json& schema, std::size_t index) {
  if (schema.is_object()) {
    if (schema.contains("title") && schema["title"].is_string()) {
      return "\"" + schema["title"].get<std::string>() + "\"";
    }
    if (schema.contains("$ref") && schema["$ref"].is_string()) {
      return schema["$ref"].get<std::string>();
    }
  }
  // Appending instead of operator+("#", ...) avoids GCC 12's false -Wrestrict at -O3 (bug 105329).
  std::string label = "#";
  label += std::to_string(index);
  return label;
}

// Keywords the validator evaluates, and annotations it may ignore. Anything else in a schema is an
// error at load time.
const std::set<std::string>& validation_keywords() {
  static const std::set<std::string> k = {"$ref",
                                          "type",
                                          "enum",
                                          "const",
                                          "properties",
                                          "required",
                                          "additionalProperties",
                                          "dependentRequired",
                                          "dependentSchemas",
                                          "items",
                                          "minItems",
                                          "maxItems",
                                          "minLength",
                                          "maxLength",
                                          "pattern",
                                          "minimum",
                                          "maximum",
                                          "exclusiveMinimum",
                                          "exclusiveMaximum",
                                          "allOf",
                                          "anyOf",
                                          "oneOf",
                                          "not"};
  return k;
}
const std::set<std::string>& annotation_keywords() {
  static const std::set<std::string> k = {
      "title",    "description",   "default",    "example",          "examples",
      "format",   "discriminator", "deprecated", "readOnly",         "writeOnly",
      "$comment", "externalDocs",  "xml",        "contentMediaType", "contentEncoding"};
  return k;
}

// ------------------------------------------------------------------------------------------------
// The validator.

class Validator {
 public:
  explicit Validator(const json& doc) : doc_(doc) {}

  const json& resolve(const std::string& ref) const {
    if (ref.empty() || ref[0] != '#') {
      throw std::runtime_error("openapi: only local $ref is supported: " + ref);
    }
    const json::json_pointer ptr(ref.substr(1));
    if (!doc_.contains(ptr)) {
      throw std::runtime_error("openapi: $ref does not resolve: " + ref);
    }
    return doc_.at(ptr);
  }

  // Follows $ref chains of OpenAPI objects (responses, headers, parameters, request bodies).
  const json& deref(const json& obj) const {
    const json* cur = &obj;
    for (int i = 0; i < 16 && cur->is_object() && cur->contains("$ref"); ++i) {
      cur = &resolve((*cur)["$ref"].get<std::string>());
    }
    return *cur;
  }

  void validate(const json& schema, const json& v, const std::string& ptr,
                std::vector<std::string>& out, int depth = 0) const {
    if (depth > 64) {
      add(out, ptr, "schema nesting deeper than 64 (a $ref cycle?)");
      return;
    }
    if (schema.is_boolean()) {
      if (!schema.get<bool>()) {
        add(out, ptr, "no value is allowed here (schema false)");
      }
      return;
    }
    if (!schema.is_object()) {
      add(out, ptr, "schema is neither an object nor a boolean");
      return;
    }
    if (schema.contains("$ref")) {
      validate(resolve(schema["$ref"].get<std::string>()), v, ptr, out, depth + 1);
    }

    if (schema.contains("type")) {
      const json& t = schema["type"];
      bool ok = false;
      if (t.is_string()) {
        ok = matches_type(t.get<std::string>(), v);
      } else {
        for (const auto& one : t) {
          ok = ok || matches_type(one.get<std::string>(), v);
        }
      }
      if (!ok) {
        add(out, ptr,
            "expected type " + (t.is_string() ? t.get<std::string>() : t.dump()) + ", got " +
                type_name(v));
        return;  // the remaining keywords would only repeat the mismatch
      }
    }
    if (schema.contains("enum")) {
      const json& e = schema["enum"];
      if (std::find(e.begin(), e.end(), v) == e.end()) {
        add(out, ptr, "must be one of " + e.dump() + ", got " + v.dump());
      }
    }
    if (schema.contains("const") && v != schema["const"]) {
      add(out, ptr, "must be " + schema["const"].dump() + ", got " + v.dump());
    }
    if (v.is_number()) {
      check_number(schema, v, ptr, out);
    }
    if (v.is_string()) {
      check_string(schema, v, ptr, out);
    }
    if (v.is_array()) {
      check_array(schema, v, ptr, out, depth);
    }
    if (v.is_object()) {
      check_object(schema, v, ptr, out, depth);
    }
    check_composition(schema, v, ptr, out, depth);
  }

 private:
  static void check_number(const json& schema, const json& v, const std::string& ptr,
                           std::vector<std::string>& out) {
    const double d = v.get<double>();
    if (!std::isfinite(d)) {
      add(out, ptr, "must be a finite number");
    }
    if (schema.contains("minimum") && !(d >= schema["minimum"].get<double>())) {
      add(out, ptr, "must be >= " + schema["minimum"].dump() + " (minimum), got " + v.dump());
    }
    if (schema.contains("maximum") && !(d <= schema["maximum"].get<double>())) {
      add(out, ptr, "must be <= " + schema["maximum"].dump() + " (maximum), got " + v.dump());
    }
    if (schema.contains("exclusiveMinimum") && !(d > schema["exclusiveMinimum"].get<double>())) {
      add(out, ptr,
          "must be > " + schema["exclusiveMinimum"].dump() + " (exclusiveMinimum), got " +
              v.dump());
    }
    if (schema.contains("exclusiveMaximum") && !(d < schema["exclusiveMaximum"].get<double>())) {
      add(out, ptr,
          "must be < " + schema["exclusiveMaximum"].dump() + " (exclusiveMaximum), got " +
              v.dump());
    }
  }

  static void check_string(const json& schema, const json& v, const std::string& ptr,
                           std::vector<std::string>& out) {
    const std::string& s = v.get_ref<const std::string&>();
    const std::size_t n = utf8_length(s);
    if (schema.contains("minLength") && n < schema["minLength"].get<std::size_t>()) {
      add(out, ptr, "must be at least " + schema["minLength"].dump() + " characters long");
    }
    if (schema.contains("maxLength") && n > schema["maxLength"].get<std::size_t>()) {
      add(out, ptr, "must be at most " + schema["maxLength"].dump() + " characters long");
    }
    if (schema.contains("pattern")) {
      const std::string pattern = schema["pattern"].get<std::string>();
      try {
        if (!std::regex_search(s, std::regex(pattern, std::regex::ECMAScript))) {
          add(out, ptr, "must match the pattern " + pattern + ", got " + v.dump());
        }
      } catch (const std::regex_error&) {
        add(out, ptr, "the schema's pattern is not a valid ECMAScript regex: " + pattern);
      }
    }
  }

  void check_array(const json& schema, const json& v, const std::string& ptr,
                   std::vector<std::string>& out, int depth) const {
    if (schema.contains("minItems") && v.size() < schema["minItems"].get<std::size_t>()) {
      add(out, ptr,
          "must have at least " + schema["minItems"].dump() + " items, has " +
              std::to_string(v.size()));
    }
    if (schema.contains("maxItems") && v.size() > schema["maxItems"].get<std::size_t>()) {
      add(out, ptr,
          "must have at most " + schema["maxItems"].dump() + " items, has " +
              std::to_string(v.size()));
    }
    if (schema.contains("items")) {
      for (std::size_t i = 0; i < v.size(); ++i) {
        validate(schema["items"], v[i], child(ptr, std::to_string(i)), out, depth + 1);
      }
    }
  }

  void check_object(const json& schema, const json& v, const std::string& ptr,
                    std::vector<std::string>& out, int depth) const {
    if (schema.contains("required")) {
      for (const auto& name : schema["required"]) {
        const std::string key = name.get<std::string>();
        if (!v.contains(key)) {
          add(out, ptr,
              "missing required property \"" + key + "\" (expected at \"" + child(ptr, key) +
                  "\")");
        }
      }
    }
    const json empty = json::object();
    const json& props = schema.contains("properties") ? schema["properties"] : empty;
    for (const auto& [key, value] : v.items()) {
      if (props.contains(key)) {
        validate(props[key], value, child(ptr, key), out, depth + 1);
      } else if (schema.contains("additionalProperties")) {
        const json& extra = schema["additionalProperties"];
        if (extra.is_boolean() && !extra.get<bool>()) {
          add(out, child(ptr, key),
              "property \"" + key + "\" is not allowed (additionalProperties: false)");
        } else {
          validate(extra, value, child(ptr, key), out, depth + 1);
        }
      }
    }
    if (schema.contains("dependentRequired")) {
      for (const auto& [key, deps] : schema["dependentRequired"].items()) {
        if (!v.contains(key)) {
          continue;
        }
        for (const auto& dep : deps) {
          const std::string d = dep.get<std::string>();
          if (!v.contains(d)) {
            std::string message = "property \"";
            message.append(key).append("\" requires property \"").append(d);
            add(out, ptr, message.append("\" (dependentRequired)"));
          }
        }
      }
    }
    if (schema.contains("dependentSchemas")) {
      for (const auto& [key, sub] : schema["dependentSchemas"].items()) {
        if (v.contains(key)) {
          validate(sub, v, ptr, out, depth + 1);
        }
      }
    }
  }

  // The branch of a failed oneOf selected by its discriminator, or nullptr.
  const json* discriminated_branch(const json& schema, const json& v, const std::string& ptr,
                                   std::vector<std::string>& out) const {
    if (!schema.contains("discriminator") || !v.is_object()) {
      return nullptr;
    }
    const json& disc = schema["discriminator"];
    const std::string prop = disc.value("propertyName", "");
    if (prop.empty()) {
      return nullptr;
    }
    if (!v.contains(prop)) {
      add(out, ptr,
          "missing required property \"" + prop + "\" (the discriminator; expected at \"" +
              child(ptr, prop) + "\")");
      return &schema;  // reported; no branch to descend into
    }
    const json& value = v[prop];
    std::string target;
    if (value.is_string() && disc.contains("mapping") &&
        disc["mapping"].contains(value.get<std::string>())) {
      target = disc["mapping"][value.get<std::string>()].get<std::string>();
    }
    if (target.empty()) {
      json allowed = json::array();
      if (disc.contains("mapping")) {
        for (const auto& [k, unused] : disc["mapping"].items()) {
          allowed.push_back(k);
        }
      }
      add(out, child(ptr, prop),
          "must be one of " + allowed.dump() + " (discriminator), got " + value.dump());
      return &schema;
    }
    for (const auto& branch : schema["oneOf"]) {
      if (branch.is_object() && branch.value("$ref", "") == target) {
        return &branch;
      }
    }
    return nullptr;
  }

  void check_composition(const json& schema, const json& v, const std::string& ptr,
                         std::vector<std::string>& out, int depth) const {
    if (schema.contains("allOf")) {
      for (const auto& sub : schema["allOf"]) {
        validate(sub, v, ptr, out, depth + 1);
      }
    }
    if (schema.contains("anyOf")) {
      std::vector<std::string> closest;
      std::string closest_label;
      bool any = false;
      std::size_t i = 0;
      for (const auto& sub : schema["anyOf"]) {
        std::vector<std::string> errs;
        validate(sub, v, ptr, errs, depth + 1);
        if (errs.empty()) {
          any = true;
          break;
        }
        if (closest.empty() || errs.size() < closest.size()) {
          closest = std::move(errs);
          closest_label = schema_label(sub, i);
        }
        ++i;
      }
      if (!any) {
        add(out, ptr, "must match at least one schema of anyOf; closest " + closest_label + ":");
        out.insert(out.end(), closest.begin(), closest.end());
      }
    }
    if (schema.contains("oneOf")) {
      const json& branches = schema["oneOf"];
      std::vector<std::string> matched;
      std::vector<std::string> closest;
      std::string closest_label;
      std::size_t i = 0;
      for (const auto& sub : branches) {
        std::vector<std::string> errs;
        validate(sub, v, ptr, errs, depth + 1);
        if (errs.empty()) {
          matched.push_back(schema_label(sub, i));
        } else if (closest.empty() || errs.size() < closest.size()) {
          closest = std::move(errs);
          closest_label = schema_label(sub, i);
        }
        ++i;
      }
      if (matched.size() > 1) {
        std::string names;
        for (const auto& m : matched) {
          names += (names.empty() ? "" : ", ") + m;
        }
        add(out, ptr,
            "must match exactly one schema of oneOf, matches " + std::to_string(matched.size()) +
                ": " + names);
      } else if (matched.empty()) {
        std::vector<std::string> disc_errs;
        const json* branch = discriminated_branch(schema, v, ptr, disc_errs);
        if (branch == &schema) {
          out.insert(out.end(), disc_errs.begin(), disc_errs.end());
        } else if (branch != nullptr) {
          validate(*branch, v, ptr, out, depth + 1);
        } else {
          add(out, ptr,
              "must match exactly one schema of oneOf, matches none; closest " + closest_label +
                  ":");
          out.insert(out.end(), closest.begin(), closest.end());
        }
      }
    }
    if (schema.contains("not")) {
      std::vector<std::string> errs;
      validate(schema["not"], v, ptr, errs, depth + 1);
      if (errs.empty()) {
        const json& n = schema["not"];
        std::string what = schema_label(n, 0);
        if (n.is_object() && n.contains("description")) {
          what += " (" + n["description"].get<std::string>() + ")";
        }
        add(out, ptr, "must not match the schema in not: " + what);
      }
    }
  }

  const json& doc_;
};

// ------------------------------------------------------------------------------------------------
// Load-time checks: every schema uses only supported keywords, every $ref resolves.

void check_schema_keywords(const json& schema, const std::string& where, const Validator& validator,
                           std::vector<std::string>& problems) {
  if (schema.is_boolean()) {
    return;
  }
  if (!schema.is_object()) {
    problems.push_back(where + ": a schema must be an object or a boolean");
    return;
  }
  for (const auto& [key, value] : schema.items()) {
    const std::string at = where + "/" + escape_token(key);
    if (key.rfind("x-", 0) == 0 || annotation_keywords().count(key) != 0) {
      continue;
    }
    if (validation_keywords().count(key) == 0) {
      problems.push_back(
          std::string(at).append(": unsupported schema keyword '").append(key).append("'"));
      continue;
    }
    if (key == "$ref") {
      try {
        validator.resolve(value.get<std::string>());
      } catch (const std::exception& e) {
        problems.push_back(at + ": " + e.what());
      }
    } else if (key == "properties" || key == "dependentSchemas") {
      for (const auto& [name, sub] : value.items()) {
        check_schema_keywords(sub, at + "/" + escape_token(name), validator, problems);
      }
    } else if (key == "items") {
      if (value.is_array()) {
        problems.push_back(at + ": the array form of items is not supported");
      } else {
        check_schema_keywords(value, at, validator, problems);
      }
    } else if (key == "additionalProperties" || key == "not") {
      check_schema_keywords(value, at, validator, problems);
    } else if (key == "allOf" || key == "anyOf" || key == "oneOf") {
      std::size_t i = 0;
      for (const auto& sub : value) {
        check_schema_keywords(sub, at + "/" + std::to_string(i++), validator, problems);
      }
    }
  }
}

// Walks the OpenAPI document (not the examples): checks every Schema Object and every $ref.
void check_document(const json& node, const std::string& where, const Validator& validator,
                    std::vector<std::string>& problems) {
  if (node.is_array()) {
    std::size_t i = 0;
    for (const auto& item : node) {
      check_document(item, where + "/" + std::to_string(i++), validator, problems);
    }
    return;
  }
  if (!node.is_object()) {
    return;
  }
  for (const auto& [key, value] : node.items()) {
    const std::string at = where + "/" + escape_token(key);
    if (key == "example" || key == "examples") {
      continue;  // example values are data, not document
    }
    if (key == "schema") {
      check_schema_keywords(value, at, validator, problems);
    } else if (key == "schemas" && where == "/components") {
      for (const auto& [name, sub] : value.items()) {
        check_schema_keywords(sub, at + "/" + escape_token(name), validator, problems);
      }
    } else if (key == "$ref" && value.is_string()) {
      try {
        validator.resolve(value.get<std::string>());
      } catch (const std::exception& e) {
        problems.push_back(at + ": " + e.what());
      }
    } else {
      check_document(value, at, validator, problems);
    }
  }
}

// ------------------------------------------------------------------------------------------------
// Media types.

struct MediaType {
  std::string essence;                        // "type/subtype", lower case
  std::map<std::string, std::string> params;  // name lower case, value unquoted
};

MediaType parse_media_type(const std::string& text) {
  MediaType m;
  std::size_t pos = text.find(';');
  m.essence = lower(trim(text.substr(0, pos)));
  while (pos != std::string::npos) {
    const std::size_t next = text.find(';', pos + 1);
    const std::string part =
        trim(text.substr(pos + 1, next == std::string::npos ? std::string::npos : next - pos - 1));
    pos = next;
    const std::size_t eq = part.find('=');
    if (part.empty() || eq == std::string::npos) {
      continue;
    }
    const std::string name = lower(trim(part.substr(0, eq)));
    std::string value = trim(part.substr(eq + 1));
    if (value.size() >= 2 && value.front() == '"' && value.back() == '"') {
      value = value.substr(1, value.size() - 2);
    }
    if (name == "charset") {
      value = lower(value);
    }
    m.params[name] = value;
  }
  return m;
}

bool essence_matches(const std::string& documented, const std::string& actual) {
  if (documented == actual || documented == "*/*") {
    return true;
  }
  if (documented.size() > 2 && documented.compare(documented.size() - 2, 2, "/*") == 0) {
    return actual.compare(0, documented.size() - 1, documented, 0, documented.size() - 1) == 0;
  }
  return false;
}

// The documented media type object for an actual Content-Type, or nullptr.
const json* match_media_type(const json& content, const std::string& content_type) {
  const MediaType actual = parse_media_type(content_type);
  const json* best = nullptr;
  int best_score = -1;
  for (const auto& [key, media] : content.items()) {
    const MediaType doc = parse_media_type(key);
    if (!essence_matches(doc.essence, actual.essence)) {
      continue;
    }
    // Strict, as generated clients match: the documented parameters are exactly the actual ones.
    if (doc.params != actual.params) {
      continue;
    }
    const int score = (doc.essence == actual.essence ? 1000 : (doc.essence == "*/*" ? 0 : 500)) +
                      static_cast<int>(doc.params.size());
    if (score > best_score) {
      best_score = score;
      best = &media;
    }
  }
  return best;
}

std::string documented_keys(const json& obj) {
  std::string keys;
  for (const auto& [key, unused] : obj.items()) {
    keys += (keys.empty() ? "" : ", ") + key;
  }
  return keys;
}

const std::set<std::string>& http_methods() {
  static const std::set<std::string> m = {"get",     "put",  "post",  "delete",
                                          "options", "head", "patch", "trace"};
  return m;
}

}  // namespace

// --------------------------------------------------------------------------------------------------

OpenApiContract::OpenApiContract(nlohmann::json document) : document_(std::move(document)) {}

OpenApiContract OpenApiContract::load(const std::string& path) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw std::runtime_error("openapi: cannot load " + path + ": " + e.what());
  }
  nlohmann::json doc = yaml_to_json(root, "");
  if (!doc.is_object() || !doc.contains("openapi") || !doc.contains("paths")) {
    throw std::runtime_error("openapi: " + path + " is not an OpenAPI document");
  }
  std::vector<std::string> problems;
  const Validator validator(doc);
  check_document(doc, "", validator, problems);
  if (!problems.empty()) {
    std::string message = "openapi: " + path + " uses what the contract checker does not support:";
    for (const auto& p : problems) {
      message += "\n  " + p;
    }
    throw std::runtime_error(message);
  }
  return OpenApiContract(std::move(doc));
}

nlohmann::json OpenApiContract::document() const { return document_; }

const nlohmann::json* OpenApiContract::find_response(const std::string& method,
                                                     const std::string& path, int status,
                                                     std::vector<std::string>& violations) const {
  const Validator validator(document_);
  const std::string m = lower(method);
  const std::string what = method + " " + path;
  const nlohmann::json& paths = document_["paths"];
  if (!paths.contains(path)) {
    if (status == 404 && document_.contains("x-cutcalc-unmatched-route")) {
      return &validator.deref(document_["x-cutcalc-unmatched-route"]["response"]);
    }
    violations.push_back(what + ": path is not documented (and status " + std::to_string(status) +
                         " is not 404)");
    return nullptr;
  }
  const nlohmann::json& item = paths[path];
  if (!item.contains(m)) {
    if (status == 405) {
      for (const auto& [key, op] : item.items()) {
        if (http_methods().count(key) != 0 && op.contains("responses") &&
            op["responses"].contains("405")) {
          return &validator.deref(op["responses"]["405"]);
        }
      }
    }
    violations.push_back(what + ": operation is not documented");
    return nullptr;
  }
  const nlohmann::json& responses = item[m]["responses"];
  for (const std::string& key :
       {std::to_string(status), std::to_string(status / 100) + "XX", std::string("default")}) {
    if (responses.contains(key)) {
      return &validator.deref(responses[key]);
    }
  }
  violations.push_back(what + ": status " + std::to_string(status) +
                       " is not documented (documented: " + documented_keys(responses) + ")");
  return nullptr;
}

std::vector<std::string> OpenApiContract::check_response(const std::string& method,
                                                         const std::string& path, int status,
                                                         const std::string& content_type,
                                                         const nlohmann::json& body) const {
  std::vector<std::string> violations;
  const nlohmann::json* response = find_response(method, path, status, violations);
  if (response == nullptr) {
    return violations;
  }
  const std::string what = method + " " + path + " " + std::to_string(status);
  if (!response->contains("content") || (*response)["content"].empty()) {
    if (!body.is_null()) {
      violations.push_back(what + ": the response is documented without a body");
    }
    return violations;
  }
  const nlohmann::json& content = (*response)["content"];
  if (trim(content_type).empty()) {
    violations.push_back(what + ": no Content-Type (documented: " + documented_keys(content) + ")");
    return violations;
  }
  const nlohmann::json* media = match_media_type(content, content_type);
  if (media == nullptr) {
    violations.push_back(what + ": Content-Type \"" + content_type +
                         "\" is not documented (documented: " + documented_keys(content) + ")");
    return violations;
  }
  // A response to HEAD has no content: what GET would send is not there to validate.
  if (media->contains("schema") && lower(method) != "head") {
    Validator(document_).validate((*media)["schema"], body, "", violations);
  }
  return violations;
}

std::vector<std::string> OpenApiContract::check_request(const std::string& method,
                                                        const std::string& path,
                                                        const nlohmann::json& body) const {
  std::vector<std::string> violations;
  const std::string m = lower(method);
  const std::string what = method + " " + path;
  const nlohmann::json& paths = document_["paths"];
  if (!paths.contains(path) || !paths[path].contains(m)) {
    violations.push_back(what + ": operation is not documented");
    return violations;
  }
  const Validator validator(document_);
  const nlohmann::json& op = paths[path][m];
  if (!op.contains("requestBody")) {
    if (!body.is_null()) {
      violations.push_back(what + ": the operation takes no request body");
    }
    return violations;
  }
  const nlohmann::json& request_body = validator.deref(op["requestBody"]);
  const nlohmann::json* media = request_body.contains("content")
                                    ? match_media_type(request_body["content"], "application/json")
                                    : nullptr;
  if (media == nullptr) {
    violations.push_back(what + ": no application/json request body is documented");
    return violations;
  }
  if (media->contains("schema")) {
    validator.validate((*media)["schema"], body, "", violations);
  }
  return violations;
}

std::vector<std::string> OpenApiContract::check_response_headers(
    const std::string& method, const std::string& path, int status,
    const std::map<std::string, std::string>& headers) const {
  std::vector<std::string> violations;
  const nlohmann::json* response = find_response(method, path, status, violations);
  if (response == nullptr || !response->contains("headers")) {
    return violations;
  }
  const Validator validator(document_);
  std::map<std::string, std::string> by_lower_name;
  for (const auto& [name, value] : headers) {
    by_lower_name.emplace(lower(name), value);
  }
  for (const auto& [name, header_ref] : (*response)["headers"].items()) {
    const nlohmann::json& header = validator.deref(header_ref);
    const auto it = by_lower_name.find(lower(name));
    if (it == by_lower_name.end()) {
      if (header.value("required", false)) {
        violations.push_back("header " + name + ": required but missing");
      }
      continue;
    }
    if (!header.contains("schema")) {
      continue;
    }
    std::vector<std::string> errs;
    validator.validate(header["schema"], nlohmann::json(it->second), "", errs);
    for (const auto& e : errs) {
      violations.push_back(std::string("header ").append(name).append(": ").append(e));
    }
  }
  return violations;
}

std::vector<std::string> OpenApiContract::check_schema(const std::string& schema_ref,
                                                       const nlohmann::json& value) const {
  std::vector<std::string> violations;
  const Validator validator(document_);
  validator.validate(validator.resolve(schema_ref), value, "", violations);
  return violations;
}

}  // namespace cutcalc::test_support
