// A request's path as the engine hands it to the app: percent-decoded by the engine itself, the
// same way as cpp-httplib decoded it when that library routed cutcalc's requests.

#include "service/http_request.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace cutcalc::service {
namespace {

TEST(PercentDecodePath, DecodesTwoDigitEscapesInEitherCase) {
  EXPECT_EQ(percent_decode_path("/v1/entry%2Dlength"), "/v1/entry-length");
  EXPECT_EQ(percent_decode_path("/a%2fb%2Fc"), "/a/b/c");
  EXPECT_EQ(percent_decode_path("%41%62"), "Ab");
  EXPECT_EQ(percent_decode_path("/%00x"), std::string("/\0x", 3));
  EXPECT_EQ(percent_decode_path("/%ff"), "/\xff");
}

TEST(PercentDecodePath, LeavesWhatIsNoEscapeAsItIs) {
  EXPECT_EQ(percent_decode_path("/a+b"), "/a+b");  // '+' is no space in a path
  EXPECT_EQ(percent_decode_path("/%"), "/%");
  EXPECT_EQ(percent_decode_path("/%4"), "/%4");
  EXPECT_EQ(percent_decode_path("/%zz"), "/%zz");
  EXPECT_EQ(percent_decode_path("/%%41"), "/%A");
  EXPECT_EQ(percent_decode_path("/%u12"), "/%u12");
  EXPECT_EQ(percent_decode_path("/%u12G4"), "/%u12G4");
}

TEST(PercentDecodePath, DecodesTheUnicodeFormAsUtf8) {
  EXPECT_EQ(percent_decode_path("/%u0076"), "/v");
  EXPECT_EQ(percent_decode_path("/%u00e9"), "/\xc3\xa9");
  EXPECT_EQ(percent_decode_path("/%u0416"), "/\xd0\x96");
  EXPECT_EQ(percent_decode_path("/%u20AC"), "/\xe2\x82\xac");
  EXPECT_EQ(percent_decode_path("/%uFFFF"), "/\xef\xbf\xbf");
  // A surrogate is no character: the escape gives nothing.
  EXPECT_EQ(percent_decode_path("/a%uD800b"), "/ab");
}

TEST(RequestPath, IsTheDecodedPathOfTheTarget) {
  std::string scratch;
  EXPECT_EQ(request_path("/v1/entry-length?x=%41", scratch), "/v1/entry-length");
  EXPECT_EQ(request_path("/v1/%65ntry-length", scratch), "/v1/entry-length");
  EXPECT_EQ(request_path("http://cutcalc/v1/x?y", scratch), "/v1/x");
  EXPECT_EQ(request_path("http://cutcalc", scratch), "/");
  EXPECT_EQ(request_path("*", scratch), "*");
}

TEST(OwnedRequest, KeepsEveryPartOfTheRequestAfterTheBuffersAreGone) {
  auto buffer = std::make_unique<std::string>("POST/v1/x?a/v1/xContent-Typeapplication/json{}");
  const std::string_view bytes = *buffer;
  const std::vector<HeaderField> fields{{bytes.substr(16, 12), bytes.substr(28, 16)}};
  HttpRequest framed;
  framed.method = bytes.substr(0, 4);
  framed.target = bytes.substr(4, 7);
  framed.path = bytes.substr(11, 5);
  framed.http11 = false;
  framed.fields = fields;
  framed.body = bytes.substr(44);
  framed.phase = ServerPhase::draining;
  OwnedRequest owned(framed);
  buffer->assign(buffer->size(), '#');  // the connection's buffer reused
  buffer.reset();

  const HttpRequest& request = owned.request();
  EXPECT_EQ(request.method, "POST");
  EXPECT_EQ(request.target, "/v1/x?a");
  EXPECT_EQ(request.path, "/v1/x");
  EXPECT_FALSE(request.http11);
  EXPECT_EQ(request.header("content-type"), "application/json");
  EXPECT_EQ(request.body, "{}");
  EXPECT_EQ(request.phase, ServerPhase::draining);
  EXPECT_EQ(request.addresses, nullptr);
  // The body is the work's to let go of once read.
  owned.body_storage().clear();
  owned.body_storage().shrink_to_fit();
  EXPECT_EQ(owned.request().method, "POST");
}

}  // namespace
}  // namespace cutcalc::service
