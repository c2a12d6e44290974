#pragma once
// The real cutcalc HTTP app on an ephemeral loopback port, for API tests, plus a small client.

#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <httplib.h>
#include <nlohmann/json.hpp>

#include "service/http_app.h"

namespace cutcalc::testing {

class TestServer {
 public:
  // `cors_origins` as --cors-origin gives them (none: the default configuration).
  explicit TestServer(std::vector<std::string> cors_origins = {});
  ~TestServer();
  TestServer(const TestServer&) = delete;
  TestServer& operator=(const TestServer&) = delete;

  [[nodiscard]] int port() const { return port_; }
  [[nodiscard]] const service::HttpApp& app() const { return *app_; }
  // A fresh client for this server (clients are not thread-safe; use one per thread), its
  // exchanges logged for the contract check (support/exchange_log.h).
  [[nodiscard]] std::unique_ptr<httplib::Client> client() const;

  // The one server of this test process, started on first use.
  static TestServer& shared();

 private:
  std::unique_ptr<service::HttpApp> app_;
  std::thread serving_;
  int port_ = -1;
};

struct JsonReply {
  int status = 0;
  std::string content_type;
  std::string body;
  nlohmann::json json;  // discarded (is_discarded()) when the body is not JSON
  httplib::Headers headers;
};

// POSTs `body` to `path` with the given content type; status 0 when the connection failed.
JsonReply post(const std::string& path, const std::string& body,
               const std::string& content_type = "application/json");
JsonReply get(const std::string& path);

// A reference case file from shared/reference, parsed.
nlohmann::json load_reference(const std::string& file_name);

}  // namespace cutcalc::testing
