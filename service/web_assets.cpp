#include "service/web_assets.h"

#include <string>

namespace cutcalc::service {
const WebAsset* find_web_asset(std::string_view url_path) {
  for (const WebAsset& asset : web_assets()) {
    if (asset.url_path == url_path) {
      return &asset;
    }
  }
  return nullptr;
}

void install_web_routes(RouteTable& routes) {
  for (const WebAsset& asset : web_assets()) {
    routes.add_get(std::string(asset.url_path), [&asset](const HttpRequest&, HttpResponse& res) {
      res.set_header("Content-Security-Policy", kWebContentSecurityPolicy);
      // Revalidate on every load: a new binary must never run an old page's script.
      res.set_header("Cache-Control", "no-cache");
      res.set_header("Referrer-Policy", "no-referrer");
      res.set_content(std::string(asset.bytes), std::string(asset.content_type));
    });
  }
}

}  // namespace cutcalc::service
