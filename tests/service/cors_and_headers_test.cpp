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

const std::string kCorsBody =
    R"({"cutter_diameter_mm": 20, "entry": {"contour": "straight", "width_mm": 60}})";

std::string post_from(const std::string& origin) {
  return "POST /v1/entry-length HTTP/1.1\r\nHost: x\r\nConnection: close\r\nOrigin: " + origin +
         "\r\nContent-Type: application/json\r\nContent-Length: " +
         std::to_string(kCorsBody.size()) + "\r\n\r\n" + kCorsBody;
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

// A browser sees an engine's rejection (a body over the limit, malformed framing) as the problem
// it is, not as a network error: the rejection carries the CORS headers too.
TEST(Cors, EngineRejectionsCarryAllowOriginForAnAllowedOrigin) {
  ServiceProcess service(CUTCALC_BINARY, {"--cors-origin", "https://mes.example"});
  const std::string too_large =
      exchange(service.port(),
               "POST /v1/entry-length HTTP/1.1\r\nHost: x\r\nOrigin: https://mes.example\r\n"
               "Content-Type: application/json\r\nContent-Length: 10000000\r\n\r\n");
  EXPECT_NE(too_large.find("HTTP/1.1 413"), std::string::npos) << too_large;
  EXPECT_NE(too_large.find("Access-Control-Allow-Origin: https://mes.example\r\n"),
            std::string::npos)
      << too_large;
  const std::string malformed =
      exchange(service.port(),
               "POST /v1/entry-length HTTP/1.1\r\nHost: x\r\nOrigin: https://mes.example\r\n"
               "Content-Length: 1\r\nContent-Length: 2\r\n\r\nab");
  EXPECT_NE(malformed.find("HTTP/1.1 400"), std::string::npos) << malformed;
  EXPECT_NE(malformed.find("Access-Control-Allow-Origin: https://mes.example\r\n"),
            std::string::npos)
      << malformed;
  const std::string other =
      exchange(service.port(),
               "POST /v1/entry-length HTTP/1.1\r\nHost: x\r\nOrigin: https://evil.example\r\n"
               "Content-Length: 10000000\r\n\r\n");
  EXPECT_NE(other.find("HTTP/1.1 413"), std::string::npos) << other;
  EXPECT_EQ(other.find("Access-Control-Allow-Origin"), std::string::npos) << other;

  ServiceProcess any(CUTCALC_BINARY, {"--cors-origin", "*"});
  const std::string unread = exchange(any.port(), "BAD\r\n\r\n");  // no head to read Origin from
  EXPECT_NE(unread.find("HTTP/1.1 400"), std::string::npos) << unread;
  EXPECT_NE(unread.find("Access-Control-Allow-Origin: *\r\n"), std::string::npos) << unread;
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
