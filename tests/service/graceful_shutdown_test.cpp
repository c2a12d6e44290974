// SIGTERM/SIGINT: stop accepting, answer every request already in flight, exit 0.

#include <gtest/gtest.h>

#include <csignal>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "support/service_process.h"

namespace cutcalc::testing {
namespace {

const std::string kShutdownBody =
    R"({"cutter_diameter_mm": 20, "entry": {"contour": "straight", "width_mm": 60}})";

std::string request_head() {
  return "POST /v1/entry-length HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
         "Content-Length: " +
         std::to_string(kShutdownBody.size()) + "\r\n\r\n";
}

void finishes_in_flight_requests_on(int signal_number) {
  ServiceProcess service(CUTCALC_BINARY, {"--log-level", "info"});
  constexpr int kInFlight = 20;
  std::vector<std::unique_ptr<RawConnection>> connections;
  for (int i = 0; i < kInFlight; ++i) {
    connections.push_back(std::make_unique<RawConnection>(service.port()));
    ASSERT_TRUE(connections.back()->connected());
    // Head and half the body: the server is now reading these requests.
    ASSERT_TRUE(connections.back()->send_all(request_head() +
                                             kShutdownBody.substr(0, kShutdownBody.size() / 2)));
  }
  // Let the server pick every connection up before the signal.
  RawConnection probe(service.port());
  ASSERT_TRUE(probe.send_all("GET /healthz HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n"));
  ASSERT_NE(probe.read_all(5000).find("200 OK"), std::string::npos);

  service.signal(signal_number);
  for (auto& connection : connections) {
    ASSERT_TRUE(connection->send_all(kShutdownBody.substr(kShutdownBody.size() / 2)));
  }
  for (auto& connection : connections) {
    const std::string reply = connection->read_all(5000);
    EXPECT_EQ(reply.rfind("HTTP/1.1 200 OK", 0), 0U) << reply;
    EXPECT_NE(reply.find("\"entry_length_mm\""), std::string::npos) << reply;
  }
  EXPECT_EQ(service.wait_exit(10000), 0) << service.output();
  EXPECT_FALSE(RawConnection(service.port()).connected()) << "still accepting after the signal";
}

TEST(GracefulShutdown, SigtermAnswersInFlightRequestsAndExitsZero) {
  finishes_in_flight_requests_on(SIGTERM);
}

TEST(GracefulShutdown, SigintAnswersInFlightRequestsAndExitsZero) {
  finishes_in_flight_requests_on(SIGINT);
}

TEST(GracefulShutdown, AccessLogHasOneLinePerRequestWithItsId) {
  ServiceProcess service(CUTCALC_BINARY, {"--log-format", "json"});
  RawConnection connection(service.port());
  ASSERT_TRUE(connection.send_all(
      "GET /healthz HTTP/1.1\r\nHost: x\r\nX-Request-Id: probe-7\r\nConnection: close\r\n\r\n"));
  connection.read_all(5000);
  service.signal(SIGTERM);
  ASSERT_EQ(service.wait_exit(10000), 0);
  const std::string log = service.output();
  EXPECT_NE(log.find(R"("event":"access","method":"GET","path":"/healthz","status":200)"),
            std::string::npos)
      << log;
  EXPECT_NE(log.find(R"("request_id":"probe-7")"), std::string::npos) << log;
  // Every line, the service's own included, is one JSON object.
  std::istringstream lines(log);
  for (std::string line; std::getline(lines, line);) {
    EXPECT_TRUE(line.empty() || nlohmann::json::accept(line)) << line;
  }
}

}  // namespace
}  // namespace cutcalc::testing
