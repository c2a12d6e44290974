// The access log as a stopped service leaves it. The stop itself (SIGTERM/SIGINT: answer every
// request already in flight, stop accepting, exit 0) is tested in restart_test.cpp.

#include <gtest/gtest.h>

#include <csignal>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "support/service_process.h"

namespace cutcalc::testing {
namespace {

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
