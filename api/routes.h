#pragma once
// The calculation endpoints of API v1: path and handler. The service registers each as POST.

#include <span>

#include "api/json_endpoint.h"

namespace cutcalc::api {

struct CalculationRoute {
  const char* path;
  JsonHandler handler;
};

std::span<const CalculationRoute> calculation_routes();

}  // namespace cutcalc::api
