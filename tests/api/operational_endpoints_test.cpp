// Health, readiness, version, metrics, the served contract, request ids, 404 and 405.

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "support/reference_compare.h"
#include "support/test_server.h"

namespace cutcalc::testing {
namespace {

TEST(Operational, HealthzSaysOk) {
  const JsonReply reply = get("/healthz");
  EXPECT_EQ(reply.status, 200);
  EXPECT_EQ(reply.json.value("status", std::string()), "ok");
}

TEST(Operational, ReadyzSaysReadyWhileServing) {
  const JsonReply reply = get("/readyz");
  EXPECT_EQ(reply.status, 200);
  EXPECT_EQ(reply.json.value("status", std::string()), "ready");
}

TEST(Operational, VersionNamesTheServiceAndItsVersion) {
  const JsonReply reply = get("/version");
  EXPECT_EQ(reply.status, 200);
  EXPECT_EQ(reply.json.value("name", std::string()), "cutcalc");
  EXPECT_FALSE(reply.json.value("version", std::string()).empty());
  EXPECT_FALSE(reply.json.value("commit", std::string()).empty());
}

TEST(Operational, OpenApiIsServedExactlyAsInTheRepository) {
  const JsonReply reply = get("/openapi.yaml");
  EXPECT_EQ(reply.status, 200);
  EXPECT_EQ(reply.content_type, "application/yaml");
  std::ifstream in(CUTCALC_OPENAPI_PATH);
  std::stringstream file;
  file << in.rdbuf();
  EXPECT_EQ(reply.body, file.str());
}

TEST(Operational, MetricsCountRequestsByRouteAndStatus) {
  post("/v1/entry-length", "not json");
  const JsonReply reply = get("/metrics");
  EXPECT_EQ(reply.status, 200);
  EXPECT_NE(reply.content_type.find("text/plain"), std::string::npos);
  EXPECT_NE(
      reply.body.find(
          R"(cutcalc_http_requests_total{route="/v1/entry-length",method="POST",status="400"})"),
      std::string::npos)
      << reply.body;
  EXPECT_NE(
      reply.body.find(
          R"(cutcalc_http_request_duration_seconds_bucket{route="/v1/entry-length",le="+Inf"})"),
      std::string::npos);
  EXPECT_NE(reply.body.find("cutcalc_http_requests_in_flight"), std::string::npos);
}

TEST(Operational, RequestIdIsEchoedWhenSafeAndGeneratedOtherwise) {
  auto client = TestServer::shared().client();
  const auto echoed = client->Get("/healthz", {{"X-Request-Id", "abc-123.X_y"}});
  ASSERT_TRUE(echoed);
  EXPECT_EQ(echoed->get_header_value("X-Request-Id"), "abc-123.X_y");
  const auto replaced = client->Get("/healthz", {{"X-Request-Id", "bad id with spaces"}});
  ASSERT_TRUE(replaced);
  const std::string generated = replaced->get_header_value("X-Request-Id");
  EXPECT_EQ(generated.size(), 16U);
  EXPECT_NE(generated, "bad id with spaces");
}

TEST(Operational, ProblemBodiesCarryTheRequestIdAndPath) {
  auto client = TestServer::shared().client();
  const auto reply =
      client->Post("/v1/entry-length", {{"X-Request-Id", "trace-42"}}, "{", "application/json");
  ASSERT_TRUE(reply);
  const auto body = nlohmann::json::parse(reply->body);
  EXPECT_EQ(body.value("request_id", std::string()), "trace-42");
  EXPECT_EQ(body.value("instance", std::string()), "/v1/entry-length");
}

TEST(Operational, UnknownPathIsNotFoundProblem) {
  const JsonReply reply = get("/v1/nothing-here");
  EXPECT_EQ(reply.status, 404);
  EXPECT_EQ(reply.content_type, "application/problem+json");
  EXPECT_EQ(reply.json.value("status", 0), 404);
}

TEST(Operational, WrongMethodIsNotAllowedWithAllowHeader) {
  const JsonReply reply = get("/v1/entry-length");
  EXPECT_EQ(reply.status, 405);
  EXPECT_EQ(reply.content_type, "application/problem+json");
  bool has_allow = false;
  for (const auto& [name, value] : reply.headers) {
    has_allow = has_allow || (name == "Allow" && value == "POST, OPTIONS");
  }
  EXPECT_TRUE(has_allow);
  EXPECT_EQ(post("/healthz", "{}").status, 405);
}

}  // namespace
}  // namespace cutcalc::testing
