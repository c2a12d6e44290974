// A route that takes whole programs (POST /v1/program-time, api::kProgramBodyBytes) reads bodies
// far over the default limit, chunked too; above its own limit it answers 413 from the head; and
// at most HttpLimits::max_large_bodies such bodies are received at once: one more is answered 503
// with Retry-After before its body is read (machine-time issue: "at most a few such bodies are
// buffered at once").

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "api/routes.h"
#include "service/http_limits.h"
#include "support/gate.h"
#include "support/http_responses.h"
#include "support/service_process.h"
#include "support/test_server.h"

namespace cutcalc::testing {
namespace {

constexpr const char* kPath = "/v1/program-time";

// A program of `lines` short feed moves and its request body.
std::string program_body(std::size_t lines) {
  std::string program = "G21 G90 G61.1\\nF3000\\n";
  for (std::size_t i = 1; i <= lines; ++i) {
    program += "G1 X" + std::to_string(i % 2 == 0 ? 0 : 1) + "\\n";
  }
  return R"({"program": ")" + program +
         R"(", "machine": {"axes": {"x": {"max_velocity_mm_per_min": 12000, )"
         R"("max_acceleration_mm_per_s2": 1000}}}})";
}

std::string head(std::size_t content_length, const std::string& path = kPath) {
  return "POST " + path + " HTTP/1.1\r\nHost: t\r\nContent-Type: application/json\r\n" +
         "Content-Length: " + std::to_string(content_length) + "\r\n\r\n";
}

ParsedResponses exchange(const std::string& bytes, int timeout_ms = 20000) {
  RawConnection connection(TestServer::shared().port());
  EXPECT_TRUE(connection.connected());
  EXPECT_TRUE(connection.send_all(bytes));
  return parse_responses(connection.read_responses(1, timeout_ms));
}

TEST(LargeBody, ProgramRouteReadsABodyFarOverTheDefaultLimit) {
  const service::HttpLimits limits;
  const std::string body = program_body(200000);  // about 1.4 MB
  ASSERT_GT(body.size(), 10 * limits.max_body_bytes);
  const ParsedResponses parsed = exchange(head(body.size()) + body);
  ASSERT_EQ(parsed.finals(), 1U) << parsed.error.value_or("");
  const HttpResponse& response = parsed.responses.back();
  ASSERT_EQ(response.status, 200) << response.body;
  EXPECT_EQ(nlohmann::json::parse(response.body).at("moves"), 200000);
}

TEST(LargeBody, ChunkedProgramIsReadWhole) {
  const std::string body = program_body(100000);
  std::string bytes = "POST " + std::string(kPath) +
                      " HTTP/1.1\r\nHost: t\r\nContent-Type: application/json\r\n"
                      "Transfer-Encoding: chunked\r\n\r\n";
  constexpr std::size_t kChunk = 60000;
  for (std::size_t at = 0; at < body.size(); at += kChunk) {
    const std::string piece = body.substr(at, kChunk);
    char size[16];
    std::snprintf(size, sizeof size, "%zx\r\n", piece.size());
    bytes += size + piece + "\r\n";
  }
  bytes += "0\r\n\r\n";
  const ParsedResponses parsed = exchange(bytes);
  ASSERT_EQ(parsed.finals(), 1U) << parsed.error.value_or("");
  EXPECT_EQ(parsed.responses.back().status, 200) << parsed.responses.back().body;
}

TEST(LargeBody, OverTheRoutesOwnLimitIs413FromTheHead) {
  const ParsedResponses parsed = exchange(head(api::kProgramBodyBytes + 1), 5000);
  ASSERT_EQ(parsed.finals(), 1U) << parsed.error.value_or("");
  EXPECT_EQ(parsed.responses.back().status, 413);
}

TEST(LargeBody, OtherRoutesKeepTheDefaultLimit) {
  const service::HttpLimits limits;
  const ParsedResponses parsed = exchange(head(limits.max_body_bytes + 1, "/v1/main-time"), 5000);
  ASSERT_EQ(parsed.finals(), 1U) << parsed.error.value_or("");
  EXPECT_EQ(parsed.responses.back().status, 413);
}

TEST(LargeBody, OneMoreThanTheCapIsRefusedBeforeItsBodyAndThePlaceComesBack) {
  const service::HttpLimits limits;
  const int port = TestServer::shared().port();
  // max_large_bodies uploads that send their head and a first piece, then stall.
  std::vector<std::unique_ptr<RawConnection>> stalled;
  for (std::size_t i = 0; i < limits.max_large_bodies; ++i) {
    stalled.push_back(std::make_unique<RawConnection>(port));
    ASSERT_TRUE(stalled.back()->send_all(head(10'000'000) + std::string(1000, ' ')));
  }
  // Every place is taken once the server has read those heads (the gauge says so); then the
  // next one is refused from its head.
  const service::ConnectionCounters& counters = TestServer::shared().app().counters();
  ASSERT_TRUE(eventually(
      [&] { return counters.large_bodies_receiving.load() == limits.max_large_bodies; }));
  const ParsedResponses parsed = exchange(head(10'000'000), 5000);
  ASSERT_EQ(parsed.finals(), 1U) << parsed.error.value_or("");
  const HttpResponse& refused = parsed.responses.back();
  ASSERT_EQ(refused.status, 503) << refused.body;
  EXPECT_EQ(refused.header("retry-after"), "1");
  const nlohmann::json problem = nlohmann::json::parse(refused.body);
  EXPECT_NE(problem.at("detail").get<std::string>().find("retry after 1 s"), std::string::npos)
      << refused.body;
  // The stalled uploads go away: their places come back.
  stalled.clear();
  const std::string body = program_body(20000);
  ASSERT_GT(body.size(), limits.max_body_bytes);
  ASSERT_TRUE(eventually([&] {
    const ParsedResponses after = exchange(head(body.size()) + body);
    return after.finals() == 1 && after.responses.back().status == 200;
  }));
}

}  // namespace
}  // namespace cutcalc::testing
