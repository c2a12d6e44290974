#include "support/test_server.h"

#include <chrono>
#include <fstream>
#include <stdexcept>

#include "support/exchange_log.h"

namespace cutcalc::testing {

TestServer::TestServer(std::vector<std::string> cors_origins) {
  service::Config config;
  config.cors_origins = std::move(cors_origins);
  config.host = "127.0.0.1";
  config.port = 0;
  config.log_level = "off";
  // Each test process stops its server at exit: no lame duck and no idle grace to wait out (the
  // restart tests run the real binary with its defaults).
  config.http.limits.lame_duck = std::chrono::milliseconds{0};
  config.http.limits.drain_idle_grace = std::chrono::milliseconds{0};
  app_ = std::make_unique<service::HttpApp>(config);
  port_ = app_->bind();
  if (port_ <= 0) {
    throw std::runtime_error("test server could not bind a loopback port");
  }
  serving_ = std::thread([this] { app_->serve(); });
}

TestServer::~TestServer() {
  app_->shutdown();
  serving_.join();
}

std::unique_ptr<httplib::Client> TestServer::client() const {
  auto client = std::make_unique<httplib::Client>("127.0.0.1", port_);
  client->set_connection_timeout(5);
  client->set_read_timeout(10);
  client->set_write_timeout(10);
  log_exchanges(*client);
  return client;
}

TestServer& TestServer::shared() {
  static TestServer server;
  return server;
}

namespace {

JsonReply to_reply(const httplib::Result& result) {
  JsonReply reply;
  if (!result) {
    return reply;
  }
  reply.status = result->status;
  reply.content_type = result->get_header_value("Content-Type");
  reply.body = result->body;
  reply.headers = result->headers;
  reply.json = nlohmann::json::parse(result->body, nullptr, false);
  return reply;
}

}  // namespace

JsonReply post(const std::string& path, const std::string& body, const std::string& content_type) {
  auto client = TestServer::shared().client();
  return to_reply(client->Post(path.c_str(), body, content_type.c_str()));
}

JsonReply get(const std::string& path) {
  auto client = TestServer::shared().client();
  return to_reply(client->Get(path.c_str()));
}

namespace {

nlohmann::json read_json_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) {
    throw std::runtime_error("cannot open " + path);
  }
  return nlohmann::json::parse(in);
}

}  // namespace

nlohmann::json load_reference(const std::string& file_name) {
  nlohmann::json document = read_json_file(std::string(CUTCALC_REFERENCE_DIR) + "/" + file_name);
  // The requests that contradict the spec they cite, corrected as the replay corrects them.
  const nlohmann::json corrections = read_json_file(CUTCALC_REFERENCE_CORRECTIONS);
  for (const auto& correction : corrections.at("corrections")) {
    if (correction.at("file") != file_name) {
      continue;
    }
    for (auto& item : document.at("cases")) {
      if (item.at("id") == correction.at("id")) {
        item.at("request").merge_patch(correction.at("request"));
      }
    }
  }
  return document;
}

}  // namespace cutcalc::testing
