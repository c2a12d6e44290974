#pragma once
// Every path the service answers and the methods it accepts there, for 404/405, OPTIONS, CORS
// preflights and metric labels.

#include <string>
#include <string_view>
#include <vector>

#include "api/json_endpoint.h"

namespace cutcalc::service {

// The method a path's handler takes.
enum class RouteMethod { get, post };

struct RouteEntry {
  std::string path;
  std::string allow;  // the Allow header value: "GET, HEAD, OPTIONS" or "POST, OPTIONS"
  api::JsonHandler calculation = nullptr;  // a POST calculation's handler, answered at routing
};

class RouteTable {
 public:
  // The one place that says which methods a path answers (405's and OPTIONS' Allow, a preflight's
  // Access-Control-Allow-Methods): its handler's method, HEAD with GET (the library answers HEAD
  // from the GET handler, without the body) and OPTIONS everywhere (answered before routing).
  void add(std::string path, RouteMethod method) {
    routes_.push_back(
        {std::move(path), method == RouteMethod::get ? "GET, HEAD, OPTIONS" : "POST, OPTIONS"});
  }
  void add_calculation(std::string path, api::JsonHandler handler) {
    add(std::move(path), RouteMethod::post);
    routes_.back().calculation = handler;
  }
  [[nodiscard]] const std::vector<RouteEntry>& entries() const { return routes_; }
  // The entry for an exact path, or nullptr.
  [[nodiscard]] const RouteEntry* find(std::string_view path) const {
    for (const RouteEntry& route : routes_) {
      if (route.path == path) {
        return &route;
      }
    }
    return nullptr;
  }
  [[nodiscard]] static bool allows(const RouteEntry& route, std::string_view method) {
    std::string_view allow = route.allow;
    while (!allow.empty()) {
      const auto comma = allow.find(',');
      std::string_view token = allow.substr(0, comma);
      while (!token.empty() && token.front() == ' ') {
        token.remove_prefix(1);
      }
      if (token == method) {
        return true;
      }
      allow = comma == std::string_view::npos ? std::string_view{} : allow.substr(comma + 1);
    }
    return false;
  }

 private:
  std::vector<RouteEntry> routes_;
};

}  // namespace cutcalc::service
