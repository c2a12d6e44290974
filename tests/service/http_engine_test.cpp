// The HTTP engine at the byte level, over real loopback connections to the real service: request
// smuggling shapes answered once, pipelines answered in order, 100-continue, the connection cap,
// and the engine's own errors as problem+json that openapi.yaml describes.

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "service/http_app.h"
#include "support/http_responses.h"
#include "support/project_contract.h"
#include "support/service_process.h"
#include "support/test_server.h"

namespace cutcalc::testing {
namespace {

constexpr int kEngineTimeoutMs = 5000;

const std::string kGroove =
    R"({"feed_mm": 0.2, "nose_radius_mm": 0.8, "minor_edge_angle_deg": 10})";

std::string post_request(const std::string& path, const std::string& body,
                         const std::string& extra_headers = {}) {
  return "POST " + path + " HTTP/1.1\r\nHost: cutcalc\r\nContent-Type: application/json\r\n" +
         extra_headers + "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body;
}

std::string get_request(const std::string& path, const std::string& extra_headers = {}) {
  return "GET " + path + " HTTP/1.1\r\nHost: cutcalc\r\n" + extra_headers + "\r\n";
}

struct Outcome {
  ParsedResponses parsed;
  bool closed = false;
  std::string bytes;
};

// Sends `bytes` on a fresh connection and reads until the server closes it (or 5 s pass).
Outcome send_and_read_to_close(const std::string& bytes, int port = TestServer::shared().port()) {
  RawConnection connection(port);
  EXPECT_TRUE(connection.connected());
  connection.send_all(bytes);
  Outcome outcome;
  outcome.closed = connection.read_until_closed(kEngineTimeoutMs, outcome.bytes);
  outcome.parsed = parse_responses(outcome.bytes);
  EXPECT_FALSE(outcome.parsed.error) << *outcome.parsed.error << "\n" << outcome.bytes;
  return outcome;
}

// The one response of a rejected request: status, problem+json per openapi.yaml, X-Request-Id.
void expect_single_problem(const Outcome& outcome, int status, const std::string& type) {
  ASSERT_EQ(outcome.parsed.finals(), 1U) << outcome.bytes;
  EXPECT_TRUE(outcome.closed) << "the connection stayed open after the rejection";
  const HttpResponse& response = outcome.parsed.responses.back();
  EXPECT_EQ(response.status, status);
  EXPECT_EQ(response.header("content-type"), "application/problem+json");
  EXPECT_EQ(response.header("connection"), "close");
  const auto body = nlohmann::json::parse(response.body);
  EXPECT_EQ(body.value("type", ""), type);
  EXPECT_EQ(body.value("request_id", ""), response.header("x-request-id"));
  EXPECT_TRUE(body.contains("instance"));
  for (const auto& violation :
       test_support::project_contract().check_schema("#/components/schemas/Problem", body)) {
    ADD_FAILURE() << "problem breaks openapi.yaml: " << violation;
  }
}

TEST(HttpEngine, ContentLengthWithChunkedIsAnsweredOnceAndClosed) {
  const Outcome outcome = send_and_read_to_close(
      "POST /v1/roughness/groove-wall HTTP/1.1\r\nHost: a\r\nContent-Length: 5\r\n"
      "Transfer-Encoding: chunked\r\n\r\n0\r\n\r\n" +
      get_request("/version"));
  expect_single_problem(outcome, 400, "urn:cutcalc:problem:bad-request");
}

TEST(HttpEngine, UnknownTransferCodingWithLengthIsAnsweredOnceAndClosed) {
  const Outcome outcome = send_and_read_to_close(
      "POST /v1/roughness/groove-wall HTTP/1.1\r\nHost: a\r\nTransfer-Encoding: xchunked\r\n"
      "Content-Length: 3\r\n\r\n{}\n" +
      get_request("/version") + get_request("/version"));
  expect_single_problem(outcome, 400, "urn:cutcalc:problem:bad-request");
}

TEST(HttpEngine, DifferingContentLengthsAreAnsweredOnceAndClosed) {
  const Outcome outcome = send_and_read_to_close(
      "POST /v1/roughness/groove-wall HTTP/1.1\r\nHost: a\r\nContent-Length: 2\r\n"
      "Content-Length: 40\r\n\r\n{}" +
      get_request("/version"));
  expect_single_problem(outcome, 400, "urn:cutcalc:problem:bad-request");
}

TEST(HttpEngine, SignedContentLengthIsAnsweredOnceAndClosed) {
  const Outcome outcome = send_and_read_to_close(
      "POST /v1/roughness/groove-wall HTTP/1.1\r\nHost: a\r\nContent-Length: +2\r\n\r\n{}" +
      get_request("/version"));
  expect_single_problem(outcome, 400, "urn:cutcalc:problem:bad-request");
}

TEST(HttpEngine, UnparsableRequestGetsAProblemWithInstanceAndRequestId) {
  const Outcome outcome =
      send_and_read_to_close("GET /healthz HTTP/1.1\r\nHost: a\r\nBad line\r\n\r\n");
  expect_single_problem(outcome, 400, "urn:cutcalc:problem:bad-request");
  EXPECT_EQ(nlohmann::json::parse(outcome.parsed.responses.back().body).value("instance", ""),
            "/healthz");
}

// The engine's own refusals come from the one catalogue: English unless the head asked for Russian
// before the fault was found.
TEST(HttpEngine, ItsOwnErrorsSpeakTheLanguageTheHeadAskedFor) {
  const std::string bad_length = "Content-Length: +2\r\n\r\n{}";
  const Outcome english =
      send_and_read_to_close("POST /v1/roughness/groove-wall HTTP/1.1\r\nHost: a\r\n" + bad_length);
  expect_single_problem(english, 400, "urn:cutcalc:problem:bad-request");
  EXPECT_EQ(english.parsed.responses.back().header("content-language"), "en");
  EXPECT_EQ(nlohmann::json::parse(english.parsed.responses.back().body).value("detail", ""),
            "the HTTP request could not be processed: Content-Length must be one number (digits "
            "only)");

  const Outcome russian = send_and_read_to_close(
      "POST /v1/roughness/groove-wall HTTP/1.1\r\nHost: a\r\nAccept-Language: ru\r\n" + bad_length);
  expect_single_problem(russian, 400, "urn:cutcalc:problem:bad-request");
  EXPECT_EQ(russian.parsed.responses.back().header("content-language"), "ru");
  EXPECT_EQ(nlohmann::json::parse(russian.parsed.responses.back().body).value("detail", ""),
            "HTTP-запрос не удалось обработать: Content-Length должен быть одним числом (только "
            "цифры)");

  const Outcome too_large = send_and_read_to_close(
      "POST /v1/roughness/groove-wall HTTP/1.1\r\nHost: a\r\nAccept-Language: ru\r\n"
      "Content-Length: 99999999\r\n\r\n");
  expect_single_problem(too_large, 413, "urn:cutcalc:problem:payload-too-large");
  EXPECT_EQ(nlohmann::json::parse(too_large.parsed.responses.back().body).value("detail", ""),
            "тело запроса превышает допустимый размер");
}

TEST(HttpEngine, BodyOfA405IsReadAsBodyNotAsTheNextRequest) {
  const std::string smuggled = get_request("/version");
  RawConnection connection(TestServer::shared().port());
  connection.send_all("DELETE /v1/roughness/bore-milling HTTP/1.1\r\nHost: a\r\nContent-Length: " +
                      std::to_string(smuggled.size()) + "\r\n\r\n" + smuggled);
  const ParsedResponses first = parse_responses(connection.read_responses(1, kEngineTimeoutMs));
  ASSERT_EQ(first.finals(), 1U);
  EXPECT_EQ(first.responses[0].status, 405);
  // Nothing more comes (the /version inside the body is not answered), and the connection still
  // serves the client's next real request.
  EXPECT_EQ(connection.read_all(300), "");
  connection.send_all(get_request("/healthz"));
  const ParsedResponses next = parse_responses(connection.read_responses(1, kEngineTimeoutMs));
  ASSERT_EQ(next.finals(), 1U);
  EXPECT_EQ(next.responses[0].status, 200);
  EXPECT_EQ(next.responses[0].body, R"({"status":"ok"})");
}

TEST(HttpEngine, BodyOfA404DoesNotSpoilTheNextRequest) {
  RawConnection connection(TestServer::shared().port());
  connection.send_all(post_request("/v1/no-such-thing", kGroove) +
                      post_request("/v1/roughness/groove-wall", kGroove));
  const ParsedResponses parsed = parse_responses(connection.read_responses(2, kEngineTimeoutMs));
  ASSERT_EQ(parsed.finals(), 2U);
  EXPECT_EQ(parsed.responses[0].status, 404);
  EXPECT_EQ(parsed.responses[1].status, 200);
}

std::string numbered_pipeline(int count) {
  std::string bytes;
  for (int i = 0; i < count; ++i) {
    bytes += post_request("/v1/roughness/groove-wall", kGroove,
                          "X-Request-Id: pipelined-" + std::to_string(i) + "\r\n");
  }
  return bytes;
}

void expect_answered_in_order(const std::string& received, int count) {
  const ParsedResponses parsed = parse_responses(received);
  ASSERT_FALSE(parsed.error) << *parsed.error;
  ASSERT_EQ(parsed.finals(), static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    EXPECT_EQ(parsed.responses[static_cast<std::size_t>(i)].status, 200);
    EXPECT_EQ(parsed.responses[static_cast<std::size_t>(i)].header("x-request-id"),
              "pipelined-" + std::to_string(i));
  }
}

TEST(HttpEngine, HundredPipelinedRequestsInOneWriteAreAnsweredInOrder) {
  RawConnection connection(TestServer::shared().port());
  connection.send_all(numbered_pipeline(100));
  expect_answered_in_order(connection.read_responses(100, kEngineTimeoutMs), 100);
}

TEST(HttpEngine, PipelinedRequestsInRandomSmallPiecesAreAnsweredInOrder) {
  const std::string bytes = numbered_pipeline(100);
  RawConnection connection(TestServer::shared().port());
  std::mt19937 random(20261125);
  std::uniform_int_distribution<std::size_t> piece(1, 40);
  for (std::size_t at = 0; at < bytes.size();) {
    const std::size_t size = std::min(piece(random), bytes.size() - at);
    ASSERT_TRUE(connection.send_all(bytes.substr(at, size)));
    at += size;
    if (random() % 8 == 0) std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  expect_answered_in_order(connection.read_responses(100, kEngineTimeoutMs), 100);
}

TEST(HttpEngine, PipelinedCalculationsEachAnswerTheirOwnBody) {
  // Calculations are answered from the body the engine framed (framed_request_body()); every
  // request of a pipeline must see its own, also when the body is empty or chunked.
  const std::string chunked_feed_025 =
      "POST /v1/roughness/groove-wall HTTP/1.1\r\nHost: a\r\nContent-Type: application/json\r\n"
      "Transfer-Encoding: chunked\r\n\r\n"
      "11\r\n{\"feed_mm\": 0.25,\r\n"
      "33\r\n \"nose_radius_mm\": 0.8, \"minor_edge_angle_deg\": 10}\r\n0\r\n\r\n";
  RawConnection connection(TestServer::shared().port());
  connection.send_all(
      post_request("/v1/roughness/groove-wall",
                   R"({"feed_mm": 0.1, "nose_radius_mm": 0.8, "minor_edge_angle_deg": 10})") +
      post_request("/v1/roughness/groove-wall", "") + chunked_feed_025 +
      post_request("/v1/roughness/groove-wall",
                   R"({"feed_mm": 0.2, "nose_radius_mm": 0.8, "minor_edge_angle_deg": 10})"));
  const ParsedResponses parsed = parse_responses(connection.read_responses(4, kEngineTimeoutMs));
  ASSERT_EQ(parsed.finals(), 4U);
  EXPECT_EQ(parsed.responses[1].status, 400) << parsed.responses[1].body;  // empty body
  double rz_um[3] = {};
  for (const auto& [response, slot] : {std::pair{0, 0}, std::pair{2, 1}, std::pair{3, 2}}) {
    const auto& answer = parsed.responses[static_cast<std::size_t>(response)];
    ASSERT_EQ(answer.status, 200) << answer.body;
    rz_um[slot] = nlohmann::json::parse(answer.body).at("rz_um").get<double>();
  }
  // R3: Rz = rho - sqrt(rho^2 - S^2/4), in micrometres.
  const auto nose_arc_um = [](double S) { return 1000.0 * (0.8 - std::sqrt(0.64 - S * S / 4)); };
  EXPECT_NEAR(rz_um[0], nose_arc_um(0.1), 1e-9);
  EXPECT_NEAR(rz_um[1], nose_arc_um(0.25), 1e-9);
  EXPECT_NEAR(rz_um[2], nose_arc_um(0.2), 1e-9);
}

TEST(HttpEngine, HeadersAreReadInAnyCaseAndTheFirstOfANameCounts) {
  RawConnection connection(TestServer::shared().port());
  const std::string out_of_range =
      R"({"feed_mm": -1, "nose_radius_mm": 0.8, "minor_edge_angle_deg": 10})";
  connection.send_all(
      "POST /v1/roughness/groove-wall HTTP/1.1\r\nHost: a\r\ncontent-TYPE: Application/JSON\r\n"
      "x-request-id: first-id\r\nX-Request-Id: second-id\r\nACCEPT-LANGUAGE: ru\r\n"
      "Accept-Language: en\r\nContent-Length: " +
      std::to_string(out_of_range.size()) + "\r\n\r\n" + out_of_range);
  const ParsedResponses parsed = parse_responses(connection.read_responses(1, kEngineTimeoutMs));
  ASSERT_EQ(parsed.finals(), 1U);
  const auto& answer = parsed.responses[0];
  EXPECT_EQ(answer.status, 422) << answer.body;
  EXPECT_EQ(answer.header("x-request-id"), "first-id");
  EXPECT_EQ(answer.header("content-language"), "ru");
}

TEST(HttpEngine, ChunkedBodyIsDecodedAndTheConnectionStaysUsable) {
  RawConnection connection(TestServer::shared().port());
  const std::size_t half = kGroove.size() / 2;
  char sizes[2][32];
  std::snprintf(sizes[0], sizeof sizes[0], "%zx", half);
  std::snprintf(sizes[1], sizeof sizes[1], "%zX", kGroove.size() - half);
  connection.send_all(
      "POST /v1/roughness/groove-wall HTTP/1.1\r\nHost: a\r\nContent-Type: "
      "application/json\r\nTransfer-Encoding: chunked\r\n\r\n" +
      std::string(sizes[0]) + ";ext\r\n" + kGroove.substr(0, half) + "\r\n" + sizes[1] + "\r\n" +
      kGroove.substr(half) + "\r\n0\r\nTrailer: x\r\n\r\n" + get_request("/healthz"));
  const ParsedResponses parsed = parse_responses(connection.read_responses(2, kEngineTimeoutMs));
  ASSERT_EQ(parsed.finals(), 2U);
  EXPECT_EQ(parsed.responses[0].status, 200) << parsed.responses[0].body;
  EXPECT_EQ(parsed.responses[1].status, 200);
}

TEST(HttpEngine, ExpectContinueGetsOneInterimResponseBeforeTheBody) {
  RawConnection connection(TestServer::shared().port());
  const std::string request =
      post_request("/v1/roughness/groove-wall", kGroove, "Expect: 100-continue\r\n");
  const std::size_t head = request.find("\r\n\r\n") + 4;
  connection.send_all(request.substr(0, head));
  EXPECT_EQ(connection.read_all(500), "HTTP/1.1 100 Continue\r\n\r\n");
  connection.send_all(request.substr(head));
  const ParsedResponses parsed = parse_responses(connection.read_responses(1, kEngineTimeoutMs));
  ASSERT_EQ(parsed.responses.size(), 1U);  // no second 100 from the library
  EXPECT_EQ(parsed.responses[0].status, 200);
}

TEST(HttpEngine, ExpectContinueWithATooLargeBodyGets413WithoutThe100) {
  const Outcome outcome = send_and_read_to_close(
      "POST /v1/roughness/groove-wall HTTP/1.1\r\nHost: a\r\nExpect: 100-continue\r\n"
      "Content-Type: application/json\r\nContent-Length: 1000000\r\n\r\n");
  expect_single_problem(outcome, 413, "urn:cutcalc:problem:payload-too-large");
  EXPECT_EQ(outcome.parsed.responses.size(), 1U);  // no 100 Continue before it
}

TEST(HttpEngine, RequestWithoutHostIsRejected) {
  const Outcome outcome = send_and_read_to_close("GET /healthz HTTP/1.1\r\n\r\n");
  expect_single_problem(outcome, 400, "urn:cutcalc:problem:bad-request");
}

TEST(HttpEngine, ConnectionsOverTheCapGet503ProblemAndClose) {
  service::Config config;
  config.host = "127.0.0.1";
  config.port = 0;
  config.log_level = "off";
  config.http.max_connections = 2;
  config.http.limits.lame_duck = std::chrono::milliseconds{0};
  service::HttpApp app(config);
  const int port = app.bind();
  ASSERT_GT(port, 0);
  std::thread serving([&app] { app.serve(); });
  {
    RawConnection first(port);
    RawConnection second(port);
    // Both are taken before the third arrives: each is answered once.
    first.send_all(get_request("/healthz"));
    second.send_all(get_request("/healthz"));
    EXPECT_EQ(parse_responses(first.read_responses(1, kEngineTimeoutMs)).finals(), 1U);
    EXPECT_EQ(parse_responses(second.read_responses(1, kEngineTimeoutMs)).finals(), 1U);
    // The third is refused as it is accepted, before it sends anything.
    RawConnection third(port);
    Outcome refused;
    refused.closed = third.read_until_closed(kEngineTimeoutMs, refused.bytes);
    refused.parsed = parse_responses(refused.bytes);
    expect_single_problem(refused, 503, "urn:cutcalc:problem:unavailable");
  }
  // Once they are gone, new connections are served again.
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  const Outcome after =
      send_and_read_to_close(get_request("/healthz", "Connection: close\r\n"), port);
  ASSERT_EQ(after.parsed.finals(), 1U);
  EXPECT_EQ(after.parsed.responses[0].status, 200);
  app.shutdown();
  serving.join();
}

}  // namespace
}  // namespace cutcalc::testing
