#include "service/web_assets.h"

#include <string>

namespace cutcalc::service {
namespace {

// The library matches handler patterns as regular expressions: route the literal path only.
std::string regex_literal(std::string_view path) {
  std::string pattern;
  for (const char c : path) {
    if (std::string_view(R"(\^$.|?*+()[]{})").find(c) != std::string_view::npos) {
      pattern += '\\';
    }
    pattern += c;
  }
  return pattern;
}

}  // namespace

const WebAsset* find_web_asset(std::string_view url_path) {
  for (const WebAsset& asset : web_assets()) {
    if (asset.url_path == url_path) {
      return &asset;
    }
  }
  return nullptr;
}

void install_web_routes(httplib::Server& server, RouteTable& routes) {
  for (const WebAsset& asset : web_assets()) {
    routes.add(std::string(asset.url_path), RouteMethod::get);
    server.Get(
        regex_literal(asset.url_path), [&asset](const httplib::Request&, httplib::Response& res) {
          res.set_header("Content-Security-Policy", kWebContentSecurityPolicy);
          // Revalidate on every load: a new binary must never run an old page's script.
          res.set_header("Cache-Control", "no-cache");
          res.set_header("Referrer-Policy", "no-referrer");
          res.set_content(asset.bytes.data(), asset.bytes.size(), std::string(asset.content_type));
        });
  }
}

}  // namespace cutcalc::service
