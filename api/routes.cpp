#include "api/routes.h"

#include <array>

#include "api/entry/entry_length_endpoint.h"
#include "api/entry/main_time_endpoint.h"
#include "api/entry/main_time_program_endpoint.h"
#include "api/kinematics/resultant_speeds_endpoint.h"
#include "api/polygon/polygon_hole_endpoint.h"
#include "api/roughness/bore_milling_endpoint.h"
#include "api/roughness/groove_wall_endpoint.h"

namespace cutcalc::api {

std::span<const CalculationRoute> calculation_routes() {
  static constexpr std::array routes = {
      CalculationRoute{"/v1/entry-length", &entry::handle_entry_length},
      CalculationRoute{"/v1/main-time", &entry::handle_main_time},
      CalculationRoute{"/v1/main-time/program", &entry::handle_main_time_program},
      CalculationRoute{"/v1/resultant-speeds", &kinematics::handle_resultant_speeds},
      CalculationRoute{"/v1/roughness/groove-wall", &roughness::handle_groove_wall},
      CalculationRoute{"/v1/roughness/bore-milling", &roughness::handle_bore_milling},
      CalculationRoute{"/v1/polygon-hole/gcode", &polygon::handle_polygon_hole},
  };
  return routes;
}

}  // namespace cutcalc::api
