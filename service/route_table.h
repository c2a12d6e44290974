#pragma once
// Every path the service answers, the methods it accepts there and what answers it: the one table
// the app routes by (GET and POST alike), and the source of 404/405, OPTIONS, CORS preflights and
// metric labels.

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "api/json_endpoint.h"
#include "service/http_request.h"
#include "service/http_response.h"

namespace cutcalc::service {

// The method a path's handler takes.
enum class RouteMethod { get, post };

// A GET route's answer (also HEAD's: the engine drops the body). Fills in `res`, which already
// carries the headers every response has.
using GetHandler = std::function<void(const HttpRequest& req, HttpResponse& res)>;

struct RouteEntry {
  std::string path;
  std::string allow;  // the Allow header value: "GET, HEAD, OPTIONS" or "POST, OPTIONS"
  GetHandler get;     // a GET route's handler
  api::JsonHandler calculation = nullptr;  // a POST calculation's handler
  bool heavy = false;  // the calculation runs on the calculation pool, off the event loops
};

class RouteTable {
 public:
  // The one place that says which methods a path answers (405's and OPTIONS' Allow, a preflight's
  // Access-Control-Allow-Methods): its handler's method, HEAD with GET (the engine answers HEAD
  // from the GET handler, without the body) and OPTIONS everywhere (answered before routing).
  void add_get(std::string path, GetHandler handler) {
    routes_.push_back({std::move(path), allow_of(RouteMethod::get), std::move(handler)});
  }
  void add_calculation(std::string path, api::JsonHandler handler, bool heavy) {
    routes_.push_back({std::move(path), allow_of(RouteMethod::post), {}, handler, heavy});
  }
  [[nodiscard]] static std::string allow_of(RouteMethod method) {
    return method == RouteMethod::get ? "GET, HEAD, OPTIONS" : "POST, OPTIONS";
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
