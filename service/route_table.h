#pragma once
// Every path the service answers and the methods it accepts there, for 404/405 and metric labels.

#include <string>
#include <string_view>
#include <vector>

namespace cutcalc::service {

struct RouteEntry {
  std::string path;
  std::string allow;  // the Allow header value, e.g. "POST" or "GET, HEAD"
};

class RouteTable {
 public:
  void add(std::string path, std::string allow) {
    routes_.push_back({std::move(path), std::move(allow)});
  }
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
