#include "api/routes.h"

#include <algorithm>
#include <array>

#include "api/entry/entry_length_endpoint.h"
#include "api/entry/main_time_endpoint.h"
#include "api/entry/main_time_program_endpoint.h"
#include "api/entry/main_time_request.h"
#include "api/grooving/grooving_cycle_endpoint.h"
#include "api/kinematics/resultant_speeds_endpoint.h"
#include "api/lathe_flat/lathe_flat_endpoint.h"
#include "api/machine_time/program_time_endpoint.h"
#include "api/polygon/polygon_hole_endpoint.h"
#include "api/roughness/bore_milling_endpoint.h"
#include "api/roughness/groove_wall_endpoint.h"

namespace cutcalc::api {

std::span<const CalculationRoute> calculation_routes() {
  using enum AnswerForms;
  static constexpr std::array routes = {
      CalculationRoute{.path = "/v1/entry-length",
                       .handler = &entry::handle_entry_length,
                       .plot = {"include_scheme", "true", ""},
                       .reference_files = {"entry-length.json"},
                       .page_section = "entry",
                       .page_module = "sections/entry_and_main_time.js"},
      CalculationRoute{.path = "/v1/main-time",
                       .handler = &entry::handle_main_time,
                       .reference_files = {"main-time.json", "next/main-time.json"},
                       .page_section = "entry",
                       .page_module = "sections/entry_and_main_time.js"},
      CalculationRoute{.path = "/v1/main-time/program",
                       .handler = &entry::handle_main_time_program,
                       .forms = json_and_plain_text_program,
                       .program = &entry::kPassProgram,
                       .heavy = true,
                       .reference_files = {"main-time-program.json"},
                       .page_section = "entry",
                       .page_module = "sections/entry_and_main_time.js"},
      CalculationRoute{.path = "/v1/resultant-speeds",
                       .handler = &kinematics::handle_resultant_speeds,
                       .plot = {"arc_samples", "91", "contact_angles_deg"},
                       .reference_files = {"resultant-speeds.json"},
                       .page_section = "speeds",
                       .page_module = "sections/resultant_speeds.js"},
      CalculationRoute{
          .path = "/v1/roughness/groove-wall",
          .handler = &roughness::handle_groove_wall,
          .plot = {"curve_points", "121", ""},
          .reference_files = {"roughness-groove-wall.json", "next/roughness-groove-wall.json"},
          .page_section = "groove",
          .page_module = "sections/groove_roughness.js"},
      CalculationRoute{
          .path = "/v1/roughness/bore-milling",
          .handler = &roughness::handle_bore_milling,
          .plot = {"curve_points", "121", ""},
          .reference_files = {"roughness-bore-milling.json", "next/roughness-bore-milling.json"},
          .page_section = "bore",
          .page_module = "sections/bore_roughness.js"},
      CalculationRoute{.path = "/v1/polygon-hole/gcode",
                       .handler = &polygon::handle_polygon_hole,
                       .forms = json_and_plain_text_program,
                       .program = &polygon::kPolygonProgram,
                       .heavy = true,
                       .plot = {"include_geometry", "true", ""},
                       .reference_files = {"polygon-hole.json", "next/polygon-hole.json"},
                       .page_section = "polygon",
                       .page_module = "sections/polygon_hole.js"},
      CalculationRoute{.path = "/v1/grooving/cycle",
                       .handler = &grooving::handle_grooving_cycle,
                       .forms = json_and_plain_text_program,
                       .program = &grooving::kGroovingProgram,
                       .heavy = true,
                       .reference_files = {"next/grooving-cycle.json"},
                       .page_section = "grooving",
                       .page_module = "sections/grooving_cycle.js"},
      CalculationRoute{.path = "/v1/lathe-flat",
                       .handler = &lathe_flat::handle_lathe_flat,
                       .forms = json_and_plain_text_program,
                       .program = &lathe_flat::kLatheFlatProgram,
                       .heavy = true,
                       .reference_files = {"next/lathe-flat.json"},
                       .page_section = "flat",
                       .page_module = "sections/lathe_flat.js"},
      CalculationRoute{.path = "/v1/program-time",
                       .handler = &machine_time::handle_program_time,
                       .heavy = true,
                       .plot = {"profile_points", "200", ""},
                       .reference_files = {"next/program-time.json"},
                       .page_section = "program-time",
                       .page_module = "sections/program_time.js",
                       .max_body_bytes = kProgramBodyBytes},
  };
  return routes;
}

const CalculationRoute* find_calculation_route(std::string_view path) {
  for (const CalculationRoute& route : calculation_routes()) {
    if (path == route.path) {
      return &route;
    }
  }
  return nullptr;
}

std::span<const std::string_view> reference_files_of(const CalculationRoute& route) {
  const auto end =
      std::find(route.reference_files.begin(), route.reference_files.end(), std::string_view());
  return {route.reference_files.begin(), end};
}

std::string route_slug(std::string_view path) {
  if (path.starts_with("/v1/")) {
    path.remove_prefix(4);
  }
  std::string slug(path);
  std::replace(slug.begin(), slug.end(), '/', '_');
  std::replace(slug.begin(), slug.end(), '-', '_');
  return slug;
}

}  // namespace cutcalc::api
