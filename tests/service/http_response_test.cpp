// write_response: the one place every response's bytes are made (RFC 9112 4-6), checked byte for
// byte.

#include "service/http_response.h"

#include <gtest/gtest.h>

#include <string>

namespace cutcalc::service {
namespace {

std::string written(const HttpResponse& response, bool head_only = false,
                    ConnectionAfter after = ConnectionAfter::keep_alive) {
  std::string out;
  write_response(response, head_only, after, out);
  return out;
}

HttpResponse json(int status, std::string body) {
  HttpResponse response;
  response.status = status;
  response.set_content(std::move(body), "application/json");
  return response;
}

TEST(WriteResponse, StatusLineCarriesTheReasonPhrase) {
  EXPECT_EQ(written(json(200, "{}")).rfind("HTTP/1.1 200 OK\r\n", 0), 0U);
  EXPECT_EQ(written(json(404, "{}")).rfind("HTTP/1.1 404 Not Found\r\n", 0), 0U);
  EXPECT_EQ(written(json(422, "{}")).rfind("HTTP/1.1 422 Unprocessable Content\r\n", 0), 0U);
  EXPECT_EQ(written(json(503, "{}")).rfind("HTTP/1.1 503 Service Unavailable\r\n", 0), 0U);
  EXPECT_EQ(reason_phrase(413), "Content Too Large");  // RFC 9110 15.5.14
}

TEST(WriteResponse, KeepAliveOnHttp11SaysNothingAboutTheConnection) {
  EXPECT_EQ(written(json(200, "{\"a\":1}")),
            "HTTP/1.1 200 OK\r\nContent-Type: application/json\r\nContent-Length: 7\r\n\r\n"
            "{\"a\":1}");
}

TEST(WriteResponse, CloseAndHttp10KeepAliveAreSaid) {
  EXPECT_EQ(written(json(200, "x"), false, ConnectionAfter::close),
            "HTTP/1.1 200 OK\r\nContent-Type: application/json\r\nContent-Length: 1\r\n"
            "Connection: close\r\n\r\nx");
  EXPECT_EQ(written(json(200, "x"), false, ConnectionAfter::keep_alive_http10),
            "HTTP/1.1 200 OK\r\nContent-Type: application/json\r\nContent-Length: 1\r\n"
            "Connection: keep-alive\r\n\r\nx");
}

TEST(WriteResponse, EveryResponseButNoContentHasContentLength) {
  EXPECT_EQ(written(HttpResponse{}), "HTTP/1.1 200 OK\r\nContent-Length: 0\r\n\r\n");
  EXPECT_NE(written(json(500, "")).find("\r\nContent-Length: 0\r\n"), std::string::npos);
  HttpResponse no_content;
  no_content.status = 204;
  no_content.set_header("Allow", "GET");
  no_content.body = "ignored";
  EXPECT_EQ(written(no_content), "HTTP/1.1 204 No Content\r\nAllow: GET\r\n\r\n");
}

TEST(WriteResponse, HeadKeepsContentLengthWithoutTheBody) {
  EXPECT_EQ(written(json(200, "{\"a\":1}"), true),
            "HTTP/1.1 200 OK\r\nContent-Type: application/json\r\nContent-Length: 7\r\n\r\n");
}

TEST(WriteResponse, HeadersFollowInTheOrderSet) {
  HttpResponse response = json(503, "{}");
  response.set_header("X-Request-Id", "r1");
  response.set_header("Retry-After", "1");
  response.set_header("Vary", "Origin");
  EXPECT_EQ(written(response, false, ConnectionAfter::close),
            "HTTP/1.1 503 Service Unavailable\r\nContent-Type: application/json\r\n"
            "Content-Length: 2\r\nX-Request-Id: r1\r\nRetry-After: 1\r\nVary: Origin\r\n"
            "Connection: close\r\n\r\n{}");
  EXPECT_EQ(response.header("Retry-After"), "1");
  EXPECT_TRUE(response.has_header("Vary"));
}

TEST(WriteResponse, AppendsToWhatIsAlreadyWritten) {
  std::string out = "HTTP/1.1 100 Continue\r\n\r\n";
  write_response(json(200, "x"), false, ConnectionAfter::keep_alive, out);
  EXPECT_EQ(out,
            "HTTP/1.1 100 Continue\r\n\r\nHTTP/1.1 200 OK\r\nContent-Type: application/json\r\n"
            "Content-Length: 1\r\n\r\nx");
}

}  // namespace
}  // namespace cutcalc::service
