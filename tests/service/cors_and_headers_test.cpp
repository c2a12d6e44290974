// Front-end friendliness: CORS only for configured origins, preflight answered, nosniff on
// every response, no library version in the headers.

#include <gtest/gtest.h>

#include <csignal>
#include <string>

#include "support/service_process.h"

namespace cutcalc::testing {
namespace {

std::string exchange(int port, const std::string& request) {
  RawConnection connection(port);
  EXPECT_TRUE(connection.send_all(request));
  return connection.read_all(3000);
}

const std::string kBody =
    R"({"cutter_diameter_mm": 20, "entry": {"contour": "straight", "width_mm": 60}})";

std::string post_from(const std::string& origin) {
  return "POST /v1/entry-length HTTP/1.1\r\nHost: x\r\nConnection: close\r\nOrigin: " + origin +
         "\r\nContent-Type: application/json\r\nContent-Length: " + std::to_string(kBody.size()) +
         "\r\n\r\n" + kBody;
}

TEST(Cors, ConfiguredOriginGetsAllowOriginOnAnswersAndPreflight) {
  ServiceProcess service(CUTCALC_BINARY,
                         {"--cors-origin", "https://mes.example,https://b.example"});
  const std::string answer = exchange(service.port(), post_from("https://mes.example"));
  EXPECT_NE(answer.find("HTTP/1.1 200"), std::string::npos) << answer;
  EXPECT_NE(answer.find("Access-Control-Allow-Origin: https://mes.example\r\n"), std::string::npos);
  EXPECT_NE(answer.find("Vary: Origin"), std::string::npos);

  const std::string preflight =
      exchange(service.port(),
               "OPTIONS /v1/entry-length HTTP/1.1\r\nHost: x\r\nConnection: close\r\n"
               "Origin: https://b.example\r\nAccess-Control-Request-Method: POST\r\n"
               "Access-Control-Request-Headers: content-type\r\n\r\n");
  EXPECT_NE(preflight.find("HTTP/1.1 204"), std::string::npos) << preflight;
  EXPECT_NE(preflight.find("Access-Control-Allow-Origin: https://b.example\r\n"),
            std::string::npos);
  EXPECT_NE(preflight.find("Access-Control-Allow-Methods: POST, OPTIONS"), std::string::npos);
  EXPECT_NE(preflight.find("Access-Control-Allow-Headers: Content-Type"), std::string::npos);
  service.signal(SIGTERM);
  EXPECT_EQ(service.wait_exit(10000), 0);
}

TEST(Cors, OtherOriginsAndTheDefaultGetNoAllowOrigin) {
  ServiceProcess configured(CUTCALC_BINARY, {"--cors-origin", "https://mes.example"});
  const std::string other = exchange(configured.port(), post_from("https://evil.example"));
  EXPECT_NE(other.find("HTTP/1.1 200"), std::string::npos);
  EXPECT_EQ(other.find("Access-Control-Allow-Origin"), std::string::npos) << other;

  ServiceProcess by_default(CUTCALC_BINARY);
  const std::string answer = exchange(by_default.port(), post_from("https://mes.example"));
  EXPECT_EQ(answer.find("Access-Control-Allow-Origin"), std::string::npos) << answer;
}

TEST(ResponseHeaders, EveryResponseSaysNosniffAndNamesNoLibrary) {
  ServiceProcess service(CUTCALC_BINARY);
  for (const std::string& request :
       {std::string("GET /healthz HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n"),
        std::string("GET /nowhere HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n"),
        post_from("https://a.example"),
        std::string("POST /v1/main-time HTTP/1.1\r\nHost: x\r\nConnection: close\r\n"
                    "Content-Length: 1\r\nContent-Type: application/json\r\n\r\n{")}) {
    const std::string answer = exchange(service.port(), request);
    const std::string head = answer.substr(0, answer.find("\r\n\r\n"));
    EXPECT_NE(head.find("X-Content-Type-Options: nosniff"), std::string::npos) << head;
    EXPECT_EQ(head.find("Server:"), std::string::npos) << head;
    EXPECT_EQ(head.find("httplib"), std::string::npos) << head;
  }
}

}  // namespace
}  // namespace cutcalc::testing
