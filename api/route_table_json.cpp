#include "api/route_table_json.h"

#include <string>

#include "api/routes.h"

namespace cutcalc::api {

nlohmann::json calculation_routes_json() {
  nlohmann::json rows = nlohmann::json::array();
  for (const CalculationRoute& route : calculation_routes()) {
    nlohmann::json row;
    row["path"] = route.path;
    row["slug"] = route_slug(route.path);
    row["forms"] = route.forms == AnswerForms::json_and_plain_text_program
                       ? nlohmann::json{"json", "plain_text"}
                       : nlohmann::json{"json"};
    row["plot_field"] = nullptr;
    if (!route.plot.name.empty()) {
      row["plot_field"] = {{"name", route.plot.name},
                           {"example", nlohmann::json::parse(route.plot.example)},
                           {"replaces", route.plot.replaces}};
    }
    row["reference_files"] = nlohmann::json::array();
    row["next_reference_files"] = nlohmann::json::array();
    for (const std::string_view file : reference_files_of(route)) {
      row["reference_files"].push_back(file);
      if (file.starts_with("next/")) {
        row["next_reference_files"].push_back(file);
      }
    }
    row["page_section"] = nullptr;
    row["page_module"] = nullptr;
    if (route.page_section != kNoPage) {
      row["page_section"] = route.page_section;
      row["page_module"] = route.page_module;
    }
    row["heavy"] = route.heavy;
    row["max_body_bytes"] = route.max_body_bytes;  // 0: the service's default
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace cutcalc::api
