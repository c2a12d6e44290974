// The calculator page at GET /: served from the bytes embedded at build time (equal to web/),
// under a Content-Security-Policy, with every asset it references; wrong paths and methods get
// the service's usual problem answers.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <httplib.h>
#include <nlohmann/json.hpp>

#include "service/build_info.h"
#include "service/web_assets.h"
#include "support/exchange_log.h"
#include "support/service_process.h"

#ifndef CUTCALC_WEB_DIR
#error "CUTCALC_WEB_DIR (path to the source tree's web/, a string literal) must be defined"
#endif

namespace cutcalc::testing {
namespace {

// One service for the whole file: the page is static, nothing a test does changes it.
ServiceProcess& service() {
  static ServiceProcess process(CUTCALC_BINARY);
  return process;
}

std::unique_ptr<httplib::Client> client() {
  auto c = std::make_unique<httplib::Client>("127.0.0.1", service().port());
  c->set_connection_timeout(5);
  c->set_read_timeout(10);
  log_exchanges(*c);
  return c;
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string index_html() {
  const service::WebAsset* index = service::find_web_asset("/");
  return index == nullptr ? std::string() : std::string(index->bytes);
}

// Every src="..." and href="..." of the page that names a resource of this service.
std::set<std::string> referenced_paths(const std::string& html) {
  std::set<std::string> paths;
  const std::regex attribute(R"re(\b(?:src|href)="([^"]*)")re");
  for (auto it = std::sregex_iterator(html.begin(), html.end(), attribute);
       it != std::sregex_iterator(); ++it) {
    const std::string target = (*it)[1].str();
    if (target.empty() || target.front() == '#' || target.rfind("data:", 0) == 0) {
      continue;
    }
    paths.insert(target);
  }
  return paths;
}

// The content type a path must be served with, from its extension.
std::string expected_type(const std::string& path) {
  const auto ends_with = [&](const std::string& suffix) {
    return path.size() >= suffix.size() &&
           path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  if (ends_with(".css")) {
    return "text/css; charset=utf-8";
  }
  if (ends_with(".js")) {
    return "text/javascript; charset=utf-8";
  }
  if (ends_with(".yaml")) {
    return "application/yaml";
  }
  return "text/html; charset=utf-8";
}

TEST(WebPage, RootIsTheEmbeddedPageWithCspNosniffAndNoCache) {
  const auto res = client()->Get("/");
  ASSERT_TRUE(res) << httplib::to_string(res.error());
  EXPECT_EQ(res->status, 200);
  EXPECT_EQ(res->get_header_value("Content-Type"), "text/html; charset=utf-8");
  EXPECT_EQ(res->get_header_value("X-Content-Type-Options"), "nosniff");
  EXPECT_EQ(res->get_header_value("Cache-Control"), "no-cache");
  const std::string csp = res->get_header_value("Content-Security-Policy");
  EXPECT_EQ(csp, service::kWebContentSecurityPolicy);
  for (const char* directive : {"default-src 'none'", "script-src 'self'", "style-src 'self'",
                                "connect-src 'self'", "frame-ancestors 'none'"}) {
    EXPECT_NE(csp.find(directive), std::string::npos) << directive;
  }
  EXPECT_EQ(csp.find("unsafe-inline"), std::string::npos);
  EXPECT_FALSE(res->get_header_value("X-Request-Id").empty());
  EXPECT_EQ(res->body, index_html());
  // The five calculation forms of the page's DOM contract.
  for (const char* form :
       {R"(<form id="entry-form" novalidate>)", R"(<form id="speeds-form" novalidate>)",
        R"(<form id="groove-form" novalidate>)", R"(<form id="bore-form" novalidate>)",
        R"(<form id="polygon-form" novalidate>)"}) {
    EXPECT_NE(res->body.find(form), std::string::npos) << form;
  }
}

TEST(WebPage, PageHasNoInlineScriptOrStyle) {
  const std::string html = index_html();
  ASSERT_FALSE(html.empty());
  EXPECT_EQ(html.find("style="), std::string::npos);
  EXPECT_EQ(html.find("<style"), std::string::npos);
  // Event handler attributes (onclick=...) would be inline script too.
  EXPECT_FALSE(std::regex_search(html, std::regex(R"re(\son[a-z]+\s*=)re")));
  const std::regex script(R"re(<script\b[^>]*>)re");
  int scripts = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), script);
       it != std::sregex_iterator(); ++it) {
    ++scripts;
    EXPECT_NE(it->str().find("src=\"/ui/"), std::string::npos) << it->str();
  }
  EXPECT_EQ(scripts, 1);
}

TEST(WebPage, HeadAnswersTheHeadersWithoutABody) {
  const auto res = client()->Head("/");
  ASSERT_TRUE(res) << httplib::to_string(res.error());
  EXPECT_EQ(res->status, 200);
  EXPECT_EQ(res->get_header_value("Content-Type"), "text/html; charset=utf-8");
  EXPECT_EQ(res->get_header_value("Content-Length"), std::to_string(index_html().size()));
  EXPECT_FALSE(res->get_header_value("Content-Security-Policy").empty());
  EXPECT_TRUE(res->body.empty());

  const auto css = client()->Head("/ui/app.css");
  ASSERT_TRUE(css);
  EXPECT_EQ(css->status, 200);
  EXPECT_EQ(css->get_header_value("Content-Type"), "text/css; charset=utf-8");
}

TEST(WebPage, EveryAssetThePageReferencesIsServedWithItsType) {
  const std::set<std::string> paths = referenced_paths(index_html());
  ASSERT_TRUE(paths.count("/ui/app.css") == 1 && paths.count("/ui/app.js") == 1)
      << "index.html must load /ui/app.css and /ui/app.js";
  const auto c = client();
  for (const std::string& path : paths) {
    const auto res = c->Get(path);
    ASSERT_TRUE(res) << path;
    EXPECT_EQ(res->status, 200) << path;
    EXPECT_EQ(res->get_header_value("Content-Type"), expected_type(path)) << path;
    EXPECT_EQ(res->get_header_value("X-Content-Type-Options"), "nosniff") << path;
    if (path.rfind("/ui/", 0) == 0) {
      EXPECT_EQ(res->get_header_value("Content-Security-Policy"),
                service::kWebContentSecurityPolicy)
          << path;
      EXPECT_EQ(res->get_header_value("Cache-Control"), "no-cache") << path;
    }
  }
}

TEST(WebPage, EveryModuleImportResolvesToAServedScript) {
  // The modules import each other with relative specifiers ('./core/form.js', '../core/i18n.js'):
  // each, resolved against the importing module's URL as the browser does, must be an embedded
  // asset, or the page would fail in the browser with nothing to see in a unit test.
  const std::regex import_from(R"re(\bfrom\s+'(\.\.?/[A-Za-z0-9_./-]+)')re");
  int imports = 0;
  for (const service::WebAsset& asset : service::web_assets()) {
    if (asset.content_type.rfind("text/javascript", 0) != 0) {
      continue;
    }
    const std::string source(asset.bytes);
    const std::filesystem::path folder = std::filesystem::path(asset.url_path).parent_path();
    for (auto it = std::sregex_iterator(source.begin(), source.end(), import_from);
         it != std::sregex_iterator(); ++it) {
      ++imports;
      const std::string target = (folder / (*it)[1].str()).lexically_normal().generic_string();
      EXPECT_EQ(target.rfind("/ui/", 0), 0U) << asset.file << " imports " << target;
      EXPECT_NE(service::find_web_asset(target), nullptr) << asset.file << " imports " << target;
    }
  }
  EXPECT_GE(imports, 5);
}

TEST(WebPage, EmbeddedBytesEqualTheFilesInWeb) {
  const std::filesystem::path root(CUTCALC_WEB_DIR);
  std::map<std::string, std::string> on_disk;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    const std::string relative = std::filesystem::relative(entry.path(), root).generic_string();
    if (!entry.is_regular_file() || relative.front() == '.' ||
        relative.find("/.") != std::string::npos) {
      continue;
    }
    on_disk[relative] = read_file(entry.path());
  }
  ASSERT_TRUE(on_disk.count("index.html") == 1) << root;

  std::map<std::string, std::string> embedded;
  for (const service::WebAsset& asset : service::web_assets()) {
    embedded[std::string(asset.file)] = std::string(asset.bytes);
    std::string expected_url = "/";
    if (asset.file != "index.html") {
      expected_url += asset.file;
    }
    EXPECT_EQ(asset.url_path, expected_url);
    EXPECT_EQ(std::string(asset.content_type), expected_type(std::string(asset.file)))
        << asset.file;
  }
  EXPECT_EQ(embedded.size(), on_disk.size());
  for (const auto& [file, bytes] : on_disk) {
    ASSERT_EQ(embedded.count(file), 1U) << file << " is in web/ but not embedded";
    EXPECT_TRUE(embedded[file] == bytes) << file << " differs from the embedded copy";
  }
  // And what is served is what is embedded.
  const auto res = client()->Get("/ui/app.js");
  ASSERT_TRUE(res);
  EXPECT_TRUE(res->body == on_disk["ui/app.js"]);
}

// The names of openapi.yaml's path parameter `name` (components/parameters), from its enum.
std::set<std::string> documented_names(const std::string& yaml, const std::string& parameter,
                                       const std::string& name) {
  const auto path = yaml.find("\n    " + parameter + ":\n      name: " + name + "\n");
  EXPECT_NE(path, std::string::npos) << "openapi.yaml has no " << parameter << " parameter";
  if (path == std::string::npos) return {};
  const auto open = yaml.find("enum: [", path);
  const auto close = yaml.find(']', open);
  EXPECT_TRUE(open != std::string::npos && close != std::string::npos);
  std::set<std::string> documented;
  std::stringstream list(yaml.substr(open + 7, close - open - 7));
  for (std::string item; std::getline(list, item, ',');) {
    item.erase(0, item.find_first_not_of(' '));
    item.erase(item.find_last_not_of(' ') + 1);
    documented.insert(item);
  }
  return documented;
}

TEST(WebPage, OpenApiListsExactlyTheEmbeddedAssets) {
  // openapi.yaml documents /ui/{asset} and /ui/{folder}/{module} with enums of the names
  // (components/parameters Asset, Folder, Module): they must name every asset under web/ui/ and
  // nothing else, or the contract and the binary disagree.
  const std::string yaml(service::embedded_openapi_yaml());
  std::set<std::string> top;
  std::set<std::string> folders;
  std::set<std::string> modules;
  for (const service::WebAsset& asset : service::web_assets()) {
    if (asset.url_path.rfind("/ui/", 0) != 0) {
      EXPECT_EQ(asset.url_path, "/");
      continue;
    }
    const std::string name(asset.url_path.substr(4));
    const auto slash = name.find('/');
    if (slash == std::string::npos) {
      top.insert(name);
      continue;
    }
    EXPECT_EQ(name.find('/', slash + 1), std::string::npos) << name << ": one folder deep only";
    folders.insert(name.substr(0, slash));
    EXPECT_TRUE(modules.insert(name.substr(slash + 1)).second)
        << name << ": a module name is in one folder only";
  }
  EXPECT_EQ(documented_names(yaml, "Asset", "asset"), top);
  EXPECT_EQ(documented_names(yaml, "Folder", "folder"), folders);
  EXPECT_EQ(documented_names(yaml, "Module", "module"), modules);
}

TEST(WebPage, UnknownUiPathIsAProblemJson404) {
  for (const char* path : {"/ui/nope.js", "/ui/", "/ui/app.js/x", "/index.html", "/ui/APP.JS"}) {
    const auto res = client()->Get(path);
    ASSERT_TRUE(res) << path;
    EXPECT_EQ(res->status, 404) << path;
    EXPECT_EQ(res->get_header_value("Content-Type"), "application/problem+json") << path;
    const auto problem = nlohmann::json::parse(res->body, nullptr, false);
    ASSERT_TRUE(problem.is_object()) << res->body;
    EXPECT_EQ(problem["type"], "urn:cutcalc:problem:not-found") << path;
    EXPECT_EQ(problem["status"], 404);
  }
}

TEST(WebPage, PostAndDeleteAre405WithAllow) {
  const auto c = client();
  const auto post = c->Post("/", "{}", "application/json");
  ASSERT_TRUE(post);
  EXPECT_EQ(post->status, 405);
  EXPECT_EQ(post->get_header_value("Allow"), "GET, HEAD, OPTIONS");
  EXPECT_EQ(post->get_header_value("Content-Type"), "application/problem+json");
  const auto problem = nlohmann::json::parse(post->body, nullptr, false);
  ASSERT_TRUE(problem.is_object()) << post->body;
  EXPECT_EQ(problem["type"], "urn:cutcalc:problem:method-not-allowed");

  const auto del = c->Delete("/ui/app.css");
  ASSERT_TRUE(del);
  EXPECT_EQ(del->status, 405);
  EXPECT_EQ(del->get_header_value("Allow"), "GET, HEAD, OPTIONS");
}

TEST(WebPage, MetricsLabelThePageByItsFixedRoutes) {
  const auto c = client();
  ASSERT_TRUE(c->Get("/ui/core/svg.js"));
  ASSERT_TRUE(c->Get("/ui/made-up-by-the-client.js"));
  const auto metrics = c->Get("/metrics");
  ASSERT_TRUE(metrics);
  EXPECT_NE(metrics->body.find(R"(route="/ui/core/svg.js",method="GET",status="200")"),
            std::string::npos);
  EXPECT_EQ(metrics->body.find("made-up-by-the-client"), std::string::npos);
}

}  // namespace
}  // namespace cutcalc::testing
