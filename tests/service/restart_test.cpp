// Restarts behind a reverse proxy (issue 24), against the real binary: at SIGTERM (or SIGINT) a
// lame duck (/readyz 503 while the listener still accepts, every response saying Connection:
// close), then the listener closes, requests in flight are answered and the process exits 0. And
// idle keep-alive connections give their buffers back. No timing assertions: every wait is "until
// it happens or a generous limit".

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "support/http_responses.h"
#include "support/service_process.h"
#include "support/test_server.h"

namespace cutcalc::testing {
namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

// Generous limits: reached only when the behaviour is missing.
constexpr int kAnswerLimitMs = 10000;
constexpr int kExitLimitMs = 20000;
constexpr milliseconds kUntilLimit{15000};

// The body of the first case the reference file expects a 200 for (shared/reference).
std::string valid_body(const std::string& file) {
  const nlohmann::json reference = load_reference(file);
  for (const nlohmann::json& test_case : reference.at("cases")) {
    if (test_case.at("expect").value("status", 0) == 200) return test_case.at("request").dump();
  }
  ADD_FAILURE() << "no 200 case in " << file;
  return "{}";
}

std::string groove_wall_body() { return valid_body("roughness-groove-wall.json"); }

// The head of a keep-alive POST (HTTP/1.1 keeps the connection by default).
std::string post_head(std::string_view path, std::size_t content_length) {
  return "POST " + std::string(path) +
         " HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\nContent-Length: " +
         std::to_string(content_length) + "\r\n\r\n";
}

std::string post(std::string_view path, const std::string& body) {
  return post_head(path, body.size()) + body;
}

std::string get(std::string_view path) {
  return "GET " + std::string(path) + " HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n";
}

// The one final response on `connection`, read until the peer closes; `closed` says whether it did
// within the limit.
struct LastAnswer {
  ParsedResponses parsed;
  bool closed = false;
  std::string bytes;
};

LastAnswer read_last_answer(RawConnection& connection) {
  LastAnswer answer;
  answer.closed = connection.read_until_closed(kAnswerLimitMs, answer.bytes);
  answer.parsed = parse_responses(answer.bytes);
  return answer;
}

// One request on a fresh connection; nullopt when no complete response came.
std::optional<HttpResponse> ask(int port, const std::string& request) {
  RawConnection connection(port);
  if (!connection.connected() || !connection.send_all(request)) return std::nullopt;
  const ParsedResponses parsed = parse_responses(connection.read_responses(1, kAnswerLimitMs));
  if (parsed.error || parsed.finals() != 1) return std::nullopt;
  return parsed.responses.back();
}

// Asks /readyz on fresh connections until it says 503 (the lame duck has begun) or the limit.
// Keeps the service's log pipe drained meanwhile (a full pipe would stop it).
std::optional<HttpResponse> until_readyz_503(ServiceProcess& service) {
  const auto limit = Clock::now() + kUntilLimit;
  while (Clock::now() < limit) {
    service.output();
    const auto response = ask(service.port(), get("/readyz"));
    if (response && response->status == 503) return response;
    std::this_thread::sleep_for(milliseconds{5});
  }
  return std::nullopt;
}

// Until the service has taken the signal in (or the limit): /readyz on a new connection says 503,
// or new connections are refused (no lame duck).
bool until_draining(ServiceProcess& service) {
  const auto limit = Clock::now() + kUntilLimit;
  while (Clock::now() < limit) {
    service.output();
    RawConnection connection(service.port());
    if (!connection.connected()) return true;
    if (connection.send_all(get("/readyz"))) {
      const ParsedResponses parsed = parse_responses(connection.read_responses(1, kAnswerLimitMs));
      if (parsed.finals() == 1 && parsed.responses.back().status == 503) return true;
    }
    std::this_thread::sleep_for(milliseconds{5});
  }
  return false;
}

// A gauge's value from the Prometheus text, or nullopt.
std::optional<std::uint64_t> gauge(const std::string& metrics, const std::string& name) {
  const std::string key = "\n" + name + " ";
  const auto at = metrics.find(key);
  if (at == std::string::npos) return std::nullopt;
  return std::strtoull(metrics.c_str() + at + key.size(), nullptr, 10);
}

// Reads `name` from /metrics on fresh connections until `done(value)` or the limit; the last value
// read (nullopt when none was). Keeps the service's log pipe drained meanwhile.
template <typename Done>
std::optional<std::uint64_t> until_gauge(ServiceProcess& service, const std::string& name,
                                         Done done) {
  std::optional<std::uint64_t> value;
  const auto limit = Clock::now() + kUntilLimit;
  while (Clock::now() < limit) {
    service.output();
    const auto response = ask(
        service.port(), "GET /metrics HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n");
    if (response && response->status == 200) {
      value = gauge(response->body, name);
      if (value && done(*value)) return value;
    }
    std::this_thread::sleep_for(milliseconds{20});
  }
  return value;
}

// Most of a request body, more than the metrics request's own connection could hold in buffers.
constexpr std::size_t kPartialBody = 48 * 1024;

// Sends a head and kPartialBody bytes of its body on a new connection and reads the buffer gauge
// until it counts them (or the limit); then closes that connection. The gauge is as of the event
// loops' last sweep, so a value this high tells that a sweep has run since the call began. Returns
// the last value read.
std::optional<std::uint64_t> until_a_sweep_counts_a_partial_request(ServiceProcess& service) {
  RawConnection partial(service.port());
  if (!partial.connected() ||
      !partial.send_all(post_head("/v1/roughness/groove-wall", kPartialBody + 1024) +
                        std::string(kPartialBody, ' '))) {
    return std::nullopt;
  }
  return until_gauge(service, "cutcalc_http_connection_buffer_bytes",
                     [](std::uint64_t bytes) { return bytes >= kPartialBody; });
}

TEST(Restart, IdleKeepAliveConnectionAtSigtermGetsAFullAnswerWithConnectionClose) {
  ServiceProcess service(CUTCALC_BINARY, {"--lame-duck-ms", "2000"});
  const std::string request = post("/v1/roughness/groove-wall", groove_wall_body());
  RawConnection idle(service.port());
  ASSERT_TRUE(idle.connected());
  ASSERT_TRUE(idle.send_all(request));
  const ParsedResponses first = parse_responses(idle.read_responses(1, kAnswerLimitMs));
  ASSERT_FALSE(first.error) << *first.error;
  ASSERT_EQ(first.finals(), 1U);
  ASSERT_EQ(first.responses.back().status, 200);
  ASSERT_NE(first.responses.back().header("connection"), "close") << "not kept alive";

  service.signal(SIGTERM);
  ASSERT_TRUE(until_readyz_503(service)) << "/readyz never said 503 after SIGTERM";
  // Not before the event loops have looked at their idle connections in the drain (they close
  // idle ones in their sweep once it is time).
  const auto swept = until_a_sweep_counts_a_partial_request(service);
  ASSERT_TRUE(swept && *swept >= kPartialBody) << "no sweep seen during the lame duck";
  // The connection has been idle since before the signal; a proxy now sends on it.
  ASSERT_TRUE(idle.send_all(request));
  const LastAnswer answer = read_last_answer(idle);
  ASSERT_FALSE(answer.parsed.error) << *answer.parsed.error << "\n" << answer.bytes;
  ASSERT_EQ(answer.parsed.finals(), 1U) << answer.bytes;
  const HttpResponse& response = answer.parsed.responses.back();
  EXPECT_EQ(response.status, 200) << answer.bytes;
  EXPECT_EQ(response.header("connection"), "close") << answer.bytes;
  EXPECT_NE(response.body.find("\"rz_um\""), std::string::npos) << response.body;
  EXPECT_TRUE(answer.closed) << "the server kept the connection open after Connection: close";
  EXPECT_EQ(service.wait_exit(kExitLimitMs), 0) << service.output();
}

TEST(Restart, ReadyzOnANewConnectionDuringTheDrainIs503) {
  ServiceProcess service(CUTCALC_BINARY, {"--lame-duck-ms", "2000"});
  const auto before = ask(service.port(), get("/readyz"));
  ASSERT_TRUE(before);
  EXPECT_EQ(before->status, 200);

  service.signal(SIGTERM);
  const auto readyz = until_readyz_503(service);
  ASSERT_TRUE(readyz) << "/readyz never said 503 on a new connection after SIGTERM";
  EXPECT_EQ(readyz->header("content-type").rfind("application/problem+json", 0), 0U)
      << readyz->header("content-type");
  EXPECT_EQ(readyz->header("connection"), "close");
  const nlohmann::json problem = nlohmann::json::parse(readyz->body, nullptr, false);
  ASSERT_TRUE(problem.is_object()) << readyz->body;
  EXPECT_EQ(problem.value("type", ""), "urn:cutcalc:problem:unavailable") << readyz->body;
  EXPECT_EQ(problem.value("status", 0), 503) << readyz->body;

  // The listener still accepts during the lame duck; liveness is unchanged.
  RawConnection fresh(service.port());
  ASSERT_TRUE(fresh.connected()) << "the listener closed with the signal";
  ASSERT_TRUE(fresh.send_all(get("/healthz")));
  const LastAnswer healthz = read_last_answer(fresh);
  ASSERT_FALSE(healthz.parsed.error) << *healthz.parsed.error << "\n" << healthz.bytes;
  ASSERT_EQ(healthz.parsed.finals(), 1U) << healthz.bytes;
  EXPECT_EQ(healthz.parsed.responses.back().status, 200) << healthz.bytes;
  EXPECT_EQ(healthz.parsed.responses.back().header("connection"), "close") << healthz.bytes;
  EXPECT_TRUE(healthz.closed);

  EXPECT_EQ(service.wait_exit(kExitLimitMs), 0) << service.output();
  EXPECT_FALSE(RawConnection(service.port()).connected()) << "still accepting after the exit";
}

// Requests in flight at a stop signal: as many as a busy instance holds.
constexpr int kInFlightAtStop = 50;
// One in this many is heavy (a G-code program, on the calculation pool): fewer than the pool's
// queue takes (service/http_tuning.h, 16), so that none is refused 503 for want of room.
constexpr int kHeavyEvery = 10;

// kInFlightAtStop requests half-sent at the signal, light ones on the event loop and heavy ones on
// the calculation pool, are completed after it and each answered 200 with its result and
// Connection: close, the connection then closed; the process exits 0 and no longer accepts.
void answers_requests_in_flight_at(int signal_number, const char* lame_duck_ms) {
  SCOPED_TRACE(std::string(signal_number == SIGTERM ? "SIGTERM" : "SIGINT") + ", --lame-duck-ms " +
               lame_duck_ms);
  const std::string light = groove_wall_body();
  const std::string heavy = valid_body("polygon-hole.json");
  struct InFlight {
    std::unique_ptr<RawConnection> connection;
    std::string rest;
    std::string expected_key;
  };
  ServiceProcess service(CUTCALC_BINARY, {"--lame-duck-ms", lame_duck_ms});
  std::vector<InFlight> in_flight;
  for (int i = 0; i < kInFlightAtStop; ++i) {
    const bool is_heavy = i % kHeavyEvery == 0;
    const std::string request =
        is_heavy ? post("/v1/polygon-hole/gcode", heavy) : post("/v1/roughness/groove-wall", light);
    const std::size_t half = request.size() - (is_heavy ? heavy : light).size() / 2;
    InFlight flight{std::make_unique<RawConnection>(service.port()), request.substr(half),
                    is_heavy ? "\"program\"" : "\"rz_um\""};
    ASSERT_TRUE(flight.connection->connected()) << i;
    // The head and half the body: the server is now reading this request.
    ASSERT_TRUE(flight.connection->send_all(request.substr(0, half))) << i;
    in_flight.push_back(std::move(flight));
  }
  // The server has picked the connections up once a later one is answered.
  const auto probe = ask(service.port(), get("/healthz"));
  ASSERT_TRUE(probe);
  ASSERT_EQ(probe->status, 200);

  service.signal(signal_number);
  ASSERT_TRUE(until_draining(service)) << "the signal was not taken in";
  for (InFlight& flight : in_flight) ASSERT_TRUE(flight.connection->send_all(flight.rest));
  int answered = 0;
  for (std::size_t i = 0; i < in_flight.size(); ++i) {
    const LastAnswer answer = read_last_answer(*in_flight[i].connection);
    ASSERT_FALSE(answer.parsed.error) << i << ": " << *answer.parsed.error << "\n" << answer.bytes;
    ASSERT_EQ(answer.parsed.finals(), 1U) << i << ": " << answer.bytes;
    const HttpResponse& response = answer.parsed.responses.back();
    EXPECT_EQ(response.status, 200) << i << ": " << answer.bytes.substr(0, 300);
    EXPECT_EQ(response.header("connection"), "close") << i;
    EXPECT_NE(response.body.find(in_flight[i].expected_key), std::string::npos)
        << i << ": " << response.body.substr(0, 300);
    EXPECT_TRUE(answer.closed) << i;
    answered += response.status == 200 ? 1 : 0;
  }
  EXPECT_EQ(answered, kInFlightAtStop);
  EXPECT_EQ(service.wait_exit(kExitLimitMs), 0) << service.output();
  EXPECT_FALSE(RawConnection(service.port()).connected()) << "still accepting after the exit";
}

// With a lame duck (the requests finish while the listener is open) and without (they finish
// after it has closed).
TEST(Restart, SigtermWithRequestsInFlightExitsZeroAfterAnsweringThem) {
  for (const char* lame_duck_ms : {"0", "2000"})
    answers_requests_in_flight_at(SIGTERM, lame_duck_ms);
}

// SIGINT (an interactive stop) is taken like SIGTERM.
TEST(Restart, SigintWithRequestsInFlightExitsZeroAfterAnsweringThem) {
  answers_requests_in_flight_at(SIGINT, "0");
}

TEST(IdleConnections, HoldNoBuffers) {
  constexpr std::size_t kIdle = 50;
  ServiceProcess service(CUTCALC_BINARY);
  const int port = service.port();
  const std::string request = post("/v1/roughness/groove-wall", groove_wall_body());
  std::vector<std::unique_ptr<RawConnection>> idle;
  for (std::size_t i = 0; i < kIdle; ++i) {
    idle.push_back(std::make_unique<RawConnection>(port));
    ASSERT_TRUE(idle.back()->connected()) << i;
    ASSERT_TRUE(idle.back()->send_all(request)) << i;
  }
  for (std::size_t i = 0; i < kIdle; ++i) {
    const ParsedResponses parsed = parse_responses(idle[i]->read_responses(1, kAnswerLimitMs));
    ASSERT_EQ(parsed.finals(), 1U) << i;
    ASSERT_EQ(parsed.responses.back().status, 200) << i;
    ASSERT_NE(parsed.responses.back().header("connection"), "close") << i;
  }

  // A request being received holds its buffer. Seeing it counted also tells that the gauge has
  // been summed since the idle connections were answered.
  const auto busy = until_a_sweep_counts_a_partial_request(service);
  ASSERT_TRUE(busy) << "no cutcalc_http_connection_buffer_bytes in /metrics";
  ASSERT_GE(*busy, kPartialBody) << "a connection receiving a request holds no buffer";

  // Then well below what 50 connections holding a 16 KiB read buffer each would; the connection
  // of the metrics request itself may hold one.
  constexpr std::uint64_t kSmall = kIdle * 1024;
  const auto at_rest = until_gauge(service, "cutcalc_http_connection_buffer_bytes",
                                   [](std::uint64_t bytes) { return bytes < kSmall; });
  ASSERT_TRUE(at_rest);
  EXPECT_LT(*at_rest, kSmall) << "idle keep-alive connections still hold their buffers";
  const auto open =
      until_gauge(service, "cutcalc_http_open_connections", [](std::uint64_t) { return true; });
  ASSERT_TRUE(open);
  EXPECT_GE(*open, kIdle) << "the idle connections were closed, not emptied";
}

}  // namespace
}  // namespace cutcalc::testing
