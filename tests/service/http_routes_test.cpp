// Every route the service has (its route table, not a hand-kept list), every method it answers
// there, two it does not, and an unknown path; with and without a configured CORS origin, with no
// Origin, an allowed one and another: no header field appears twice in any answer, Allow is the
// route table's value on a 405, an OPTIONS answer and a preflight's Access-Control-Allow-Methods,
// and openapi.yaml documents every answer with the exact media type sent.

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "api/routes.h"
#include "service/http_app.h"
#include "service/route_table.h"
#include "support/http_responses.h"
#include "support/project_contract.h"
#include "support/service_process.h"
#include "support/test_server.h"

namespace cutcalc::testing {
namespace {

constexpr int kRoutesTimeoutMs = 5000;
const std::string kAllowedOrigin = "http://front.example";

struct Exchange {
  std::string method;
  std::string path;
  std::optional<service::RouteEntry> route;  // none for an unknown path (a copy: the server goes)
  bool cors_configured = false;
  std::string origin;  // empty: no Origin header
  std::string accept;
  HttpResponse response;

  [[nodiscard]] std::string label() const {
    std::string text = method;
    text.append(" ").append(path);
    if (!accept.empty()) {
      text.append(" (Accept: ").append(accept).append(")");
    }
    text.append(cors_configured ? ", --cors-origin " : ", no CORS origin");
    text.append(cors_configured ? kAllowedOrigin : "");
    text.append(origin.empty() ? ", no Origin" : ", Origin: ").append(origin);
    return text;
  }
};

// The request of the first 200 case of every endpoint's reference files (the route table's:
// reference/*.json and the next/ files it lists), by endpoint.
std::map<std::string, std::string> reference_bodies() {
  std::map<std::string, std::string> bodies;
  for (const api::CalculationRoute& route : api::calculation_routes()) {
    for (const std::string_view file : api::reference_files_of(route)) {
      std::ifstream in(std::string(CUTCALC_REFERENCE_DIR) + "/" + std::string(file));
      const auto doc = nlohmann::json::parse(in);
      for (const auto& c : doc["cases"]) {
        if (c["expect"].value("status", 0) == 200) {
          bodies.emplace(doc["endpoint"].get<std::string>(), c["request"].dump());
          break;
        }
      }
    }
  }
  return bodies;
}

HttpResponse send(int port, const std::string& method, const std::string& path,
                  const std::string& origin, const std::string& accept, const std::string& body) {
  std::string request = method;
  request.append(" ").append(path).append(" HTTP/1.1\r\nHost: cutcalc\r\nConnection: close\r\n");
  if (!origin.empty()) {
    request.append("Origin: ").append(origin).append("\r\n");
  }
  if (method == "OPTIONS") {
    request.append(
        "Access-Control-Request-Method: POST\r\nAccess-Control-Request-Headers: content-type\r\n");
  }
  if (!accept.empty()) {
    request.append("Accept: ").append(accept).append("\r\n");
  }
  if (!body.empty()) {
    request.append("Content-Type: application/json\r\nContent-Length: ")
        .append(std::to_string(body.size()))
        .append("\r\n");
  }
  request.append("\r\n").append(body);
  RawConnection connection(port);
  EXPECT_TRUE(connection.send_all(request));
  std::string bytes;
  EXPECT_TRUE(connection.read_until_closed(kRoutesTimeoutMs, bytes)) << method << " " << path;
  const ParsedResponses parsed = parse_responses(bytes);
  EXPECT_FALSE(parsed.error) << *parsed.error << "\n" << bytes;
  if (parsed.responses.size() != 1) {
    ADD_FAILURE() << method << " " << path << ": " << parsed.responses.size() << " responses\n"
                  << bytes;
    return {};
  }
  return parsed.responses.front();
}

// Every exchange of the sweep, made once per test program.
const std::vector<Exchange>& sweep() {
  static const std::vector<Exchange> exchanges = [] {
    std::vector<Exchange> all;
    const std::map<std::string, std::string> bodies = reference_bodies();
    TestServer with_cors({kAllowedOrigin});
    for (const TestServer* server : {&TestServer::shared(), &with_cors}) {
      const bool cors = server == &with_cors;
      for (const std::string& origin :
           {std::string(), kAllowedOrigin, std::string("http://b.example")}) {
        const auto add = [&](const service::RouteEntry* route, const std::string& method,
                             const std::string& path, const std::string& accept = {}) {
          const auto body = bodies.find(path);
          const bool with_body = method == "POST" && route != nullptr && body != bodies.end();
          all.push_back({method, path, route == nullptr ? std::nullopt : std::optional(*route),
                         cors, origin, accept,
                         send(server->port(), method, path, origin, accept,
                              with_body ? body->second : std::string())});
        };
        for (const service::RouteEntry& route : server->app().routes().entries()) {
          for (const char* method : {"GET", "HEAD", "POST", "OPTIONS", "DELETE"}) {
            add(&route, method, route.path);
          }
          if (service::RouteTable::allows(route, "POST")) {
            add(&route, "POST", route.path, "text/plain");
          }
        }
        add(nullptr, "GET", "/nowhere");
        add(nullptr, "OPTIONS", "/nowhere");
        add(nullptr, "POST", "/v1/nowhere");
      }
    }
    return all;
  }();
  return exchanges;
}

TEST(HttpRoutes, NoHeaderFieldAppearsTwiceInAnyAnswer) {
  std::size_t checked = 0;
  for (const Exchange& e : sweep()) {
    for (const auto& [name, value] : e.response.headers) {
      EXPECT_EQ(e.response.count(name), 1U) << name << " in " << e.label();
    }
    // CORS headers are there only when configured (Vary: Origin) and the Origin is allowed; a
    // problem in a negotiated language and an answer whose warnings[] speak it (Content-Language)
    // vary by Accept-Language, an answer with a text form by Accept: one Vary field names them all.
    const std::string vary = e.response.header("vary");
    EXPECT_EQ(vary.find("Origin") != std::string::npos, e.cors_configured) << e.label();
    const bool in_language =
        e.response.header("content-type").find("problem+json") != std::string::npos ||
        (e.response.status == 200 && !e.response.header("content-language").empty());
    EXPECT_EQ(vary.find("Accept-Language") != std::string::npos, in_language) << e.label();
    const bool allowed = e.cors_configured && e.origin == kAllowedOrigin;
    EXPECT_EQ(e.response.header("access-control-allow-origin"), allowed ? e.origin : "")
        << e.label();
    ++checked;
  }
  // 2 servers x 3 origins x (5 or 6 requests per route + 3 on unknown paths).
  EXPECT_GE(checked, 2U * 3U * (5U * 20U + 3U));
}

TEST(HttpRoutes, AllowIsTheRouteTablesOn405OptionsAndPreflight) {
  std::size_t answered = 0;
  std::size_t refused = 0;
  for (const Exchange& e : sweep()) {
    if (!e.route) {
      EXPECT_EQ(e.response.status, 404) << e.label();
      continue;
    }
    if (e.method == "OPTIONS") {
      EXPECT_EQ(e.response.status, 204) << e.label();
      EXPECT_EQ(e.response.header("allow"), e.route->allow) << e.label();
      const bool preflight = e.cors_configured && e.origin == kAllowedOrigin;
      EXPECT_EQ(e.response.header("access-control-allow-methods"), preflight ? e.route->allow : "")
          << e.label();
    } else if (service::RouteTable::allows(*e.route, e.method)) {
      EXPECT_EQ(e.response.status, 200) << e.label();
      ++answered;
    } else {
      EXPECT_EQ(e.response.status, 405) << e.label();
      EXPECT_EQ(e.response.header("allow"), e.route->allow) << e.label();
      ++refused;
    }
  }
  EXPECT_GT(answered, 0U);
  EXPECT_GT(refused, 0U);
}

// The path template under `paths` that `path` falls under ("/ui/app.js" -> "/ui/{asset}"), or
// `path` itself.
std::string path_template(const nlohmann::json& paths, const std::string& path) {
  for (const auto& [name, item] : paths.items()) {
    const std::regex pattern(
        std::string("^")
            .append(std::regex_replace(name, std::regex(R"(\{[^}]+\})"), "[^/]+"))
            .append("$"));
    if (name.find('{') != std::string::npos && std::regex_match(path, pattern)) {
      return name;
    }
  }
  return path;
}

TEST(HttpRoutes, EveryAnswerIsInTheContractWithItsExactMediaType) {
  const auto& contract = test_support::project_contract();
  const nlohmann::json paths = contract.document()["paths"];
  for (const Exchange& e : sweep()) {
    const HttpResponse& r = e.response;
    const std::string path = paths.contains(e.path) ? e.path : path_template(paths, e.path);
    nlohmann::json body;  // null: no body (HEAD, 204)
    const std::string content_type = r.header("content-type");
    if (!r.body.empty()) {
      body = content_type.find("json") != std::string::npos ? nlohmann::json::parse(r.body)
                                                            : nlohmann::json(r.body);
    }
    for (const auto& v : contract.check_response(e.method, path, r.status, content_type, body)) {
      ADD_FAILURE() << e.label() << ": " << v;
    }
    std::map<std::string, std::string> headers(r.headers.begin(), r.headers.end());
    for (const auto& v : contract.check_response_headers(e.method, path, r.status, headers)) {
      ADD_FAILURE() << e.label() << ": " << v;
    }
  }
}

TEST(HttpRoutes, ContractDocumentsExactlyTheMethodsOfAllowOnEveryPath) {
  const nlohmann::json paths = test_support::project_contract().document()["paths"];
  std::set<std::string> documented_paths;
  // An app that is never served: stopping a server that has not started listening yet would hang.
  const service::HttpApp app(service::Config{});
  for (const service::RouteEntry& route : app.routes().entries()) {
    const std::string path =
        paths.contains(route.path) ? route.path : path_template(paths, route.path);
    ASSERT_TRUE(paths.contains(path)) << route.path;
    documented_paths.insert(path);
    std::string methods;
    for (const auto& [key, op] : paths[path].items()) {
      if (key == "get" || key == "head" || key == "post" || key == "options" || key == "put" ||
          key == "delete" || key == "patch" || key == "trace") {
        std::string upper = key;
        std::transform(upper.begin(), upper.end(), upper.begin(),
                       [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
        EXPECT_TRUE(service::RouteTable::allows(route, upper)) << upper << " " << path;
        methods.append(methods.empty() ? "" : ", ").append(upper);
      }
    }
    // Same count as Allow's list: nothing in Allow is left undocumented.
    EXPECT_EQ(std::count(methods.begin(), methods.end(), ','),
              std::count(route.allow.begin(), route.allow.end(), ','))
        << path << ": documented " << methods << ", Allow: " << route.allow;
  }
  EXPECT_EQ(documented_paths.size(), paths.size()) << "a documented path has no route";
}

}  // namespace
}  // namespace cutcalc::testing
