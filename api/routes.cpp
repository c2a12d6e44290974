#include "api/routes.h"

#include <array>

#include "api/entry/entry_length_endpoint.h"
#include "api/entry/main_time_endpoint.h"

namespace cutcalc::api {

std::span<const CalculationRoute> calculation_routes() {
  static constexpr std::array routes = {
      CalculationRoute{"/v1/entry-length", &entry::handle_entry_length},
      CalculationRoute{"/v1/main-time", &entry::handle_main_time},
  };
  return routes;
}

}  // namespace cutcalc::api
