#include "support/route_table_check.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>

namespace cutcalc::test_support {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// `node` with its $ref (to #/components/...) followed.
const json& deref(const json& document, const json& node) {
  if (node.is_object() && node.contains("$ref")) {
    return document.at(json::json_pointer(node["$ref"].get<std::string>().substr(1)));
  }
  return node;
}

// The property names of a schema, through $ref, allOf, oneOf and anyOf.
void collect_properties(const json& document, const json& schema, std::set<std::string>& names) {
  const json& s = deref(document, schema);
  if (!s.is_object()) {
    return;
  }
  if (s.contains("properties")) {
    for (const auto& [name, unused] : s["properties"].items()) {
      names.insert(name);
    }
  }
  for (const char* combinator : {"allOf", "oneOf", "anyOf"}) {
    if (s.contains(combinator)) {
      for (const json& part : s[combinator]) {
        collect_properties(document, part, names);
      }
    }
  }
}

std::string endpoint_of(const fs::path& file) {
  std::ifstream in(file);
  return json::parse(in).value("endpoint", "");
}

}  // namespace

std::vector<std::string> route_table_problems(const RouteTableInputs& inputs) {
  std::vector<std::string> problems;
  const json& paths = inputs.openapi.at("paths");
  std::set<std::string> slugs;
  for (const api::CalculationRoute& route : inputs.routes) {
    const std::string path = route.path;
    const std::string at = path + ": ";
    if (!slugs.insert(api::route_slug(path)).second) {
      problems.push_back(at + "its slug " + api::route_slug(path) + " is another route's");
    }
    // A program's work grows with the request (its blocks): it must not hold up an event loop.
    const bool writes_program = route.forms == api::AnswerForms::json_and_plain_text_program;
    if (writes_program && !route.heavy) {
      problems.push_back(at + "writes a program but is not heavy");
    }
    if (writes_program != (route.program != nullptr)) {
      problems.push_back(at + (writes_program ? "writes a program but names no program policy"
                                              : "names a program policy but has no text form"));
    }
    // openapi: the path, its 200 media types, the plot field.
    if (!paths.contains(path) || !paths[path].contains("post")) {
      problems.push_back(at + "no POST " + path + " in openapi.yaml");
    } else {
      const json& post = paths[path]["post"];
      const json ok = post.at("responses").value("200", json::object());
      const json answers = deref(inputs.openapi, ok).value("content", json::object());
      bool text = false;
      for (const auto& [media_type, unused] : answers.items()) {
        text = text || media_type.starts_with("text/plain");
      }
      const bool program = route.forms == api::AnswerForms::json_and_plain_text_program;
      if (text != program) {
        problems.push_back(at + (program
                                     ? "answers a text/plain program, openapi.yaml lists none"
                                     : "openapi.yaml lists a text/plain answer the route lacks"));
      }
      if (!route.plot.name.empty()) {
        std::set<std::string> members;
        const json body = deref(inputs.openapi, post.value("requestBody", json::object()));
        const json requests = body.value("content", json::object());
        for (const auto& [media_type, media] : requests.items()) {
          collect_properties(inputs.openapi, media.value("schema", json::object()), members);
        }
        for (const std::string_view member : {route.plot.name, route.plot.replaces}) {
          if (!member.empty() && !members.contains(std::string(member))) {
            problems.push_back(at + "its plot member " + std::string(member) +
                               " is not in the request schema");
          }
        }
      }
    }
    // reference files: listed ones exist and check this endpoint; every file of the endpoint is
    // listed.
    const auto files = api::reference_files_of(route);
    if (files.empty()) {
      problems.push_back(at + "no reference file");
    }
    for (const std::string_view file : files) {
      const fs::path file_path = fs::path(inputs.reference_dir) / file;
      if (!fs::is_regular_file(file_path)) {
        problems.push_back(at + "its reference file " + file_path.string() + " does not exist");
      } else if (endpoint_of(file_path) != path) {
        problems.push_back(at + "its reference file " + std::string(file) + " checks " +
                           endpoint_of(file_path));
      }
    }
    for (const auto& entry : fs::directory_iterator(inputs.reference_dir)) {
      const std::string name = entry.path().filename().string();
      if (entry.path().extension() == ".json" && endpoint_of(entry.path()) == path &&
          std::find(files.begin(), files.end(), name) == files.end()) {
        problems.push_back(at + "the reference file " + name + " is not listed");
      }
    }
    // the page
    if (route.page_section != api::kNoPage) {
      const std::string id(route.page_section);
      if (inputs.index_html.find("<section id=\"" + id + "\"") == std::string::npos) {
        problems.push_back(at + "no <section id=\"" + id + "\"> in web/index.html");
      }
      if (inputs.index_html.find("href=\"#" + id + "\"") == std::string::npos) {
        problems.push_back(at + "no nav link to #" + id + " in web/index.html");
      }
    }
  }
  for (const auto& [path, unused] : paths.items()) {
    if (path.starts_with("/v1/") &&
        std::none_of(inputs.routes.begin(), inputs.routes.end(),
                     [&](const api::CalculationRoute& route) { return path == route.path; })) {
      problems.push_back(path + ": in openapi.yaml, not in the route table (api/routes.cpp)");
    }
  }
  return problems;
}

std::vector<std::string> replayed_reference_files(const std::string& reference_dir,
                                                  std::span<const api::CalculationRoute> routes) {
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(reference_dir)) {
    if (entry.is_regular_file() && entry.path().extension() == ".json") {
      files.push_back(entry.path().filename().string());
    }
  }
  for (const api::CalculationRoute& route : routes) {
    for (const std::string_view file : api::reference_files_of(route)) {
      if (file.starts_with("next/")) {
        files.emplace_back(file);
      }
    }
  }
  std::sort(files.begin(), files.end());
  files.erase(std::unique(files.begin(), files.end()), files.end());
  return files;
}

}  // namespace cutcalc::test_support
