// classify_request() and framed_request(): where a request ends (RFC 9112 sections 2-7), and the
// request read in the same pass.

#include "service/http_framing.h"

#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <vector>

namespace cutcalc::service {
namespace {

using Verdict = RequestFrame::Verdict;

const HttpLimits kLimits;

RequestFrame frame(std::string_view input) { return classify_request(input, kLimits); }

void expect_reject(std::string_view input, HttpFault fault) {
  const RequestFrame result = frame(input);
  EXPECT_EQ(result.verdict, Verdict::reject) << input;
  EXPECT_EQ(result.fault, fault) << input;
}

TEST(ClassifyRequest, GetWithoutBodyIsCompleteAtTheEmptyLine) {
  const std::string get = "GET /healthz HTTP/1.1\r\nHost: a\r\n\r\n";
  const std::string input = get + "GET /version HTTP/1.1\r\n";  // the frame's views point here
  const RequestFrame result = frame(input);
  EXPECT_EQ(result.verdict, Verdict::complete);
  EXPECT_EQ(result.wire_bytes, get.size());
  EXPECT_EQ(result.method, "GET");
  EXPECT_EQ(result.target, "/healthz");
}

TEST(ClassifyRequest, ContentLengthBodyIsWaitedForThenEndsExactly) {
  const std::string head = "POST /v1/x HTTP/1.1\r\nHost: a\r\nContent-Length: 5\r\n\r\n";
  EXPECT_EQ(frame(head + "{\"a\"").verdict, Verdict::incomplete);
  const RequestFrame result = frame(head + "{\"a\":GET");
  ASSERT_EQ(result.verdict, Verdict::complete);
  EXPECT_EQ(result.wire_bytes, head.size() + 5);
  EXPECT_EQ(result.body_bytes, 5U);
}

TEST(ClassifyRequest, EveryPrefixOfARequestIsIncomplete) {
  const std::string request =
      "POST /v1/x HTTP/1.1\r\nHost: a\r\nTransfer-Encoding: chunked\r\n\r\n3\r\nabc\r\n0\r\n\r\n";
  for (std::size_t n = 0; n < request.size(); ++n) {
    EXPECT_EQ(frame(request.substr(0, n)).verdict, Verdict::incomplete) << n;
  }
  EXPECT_EQ(frame(request).verdict, Verdict::complete);
}

TEST(ClassifyRequest, LeadingEmptyLinesAreSkipped) {
  const RequestFrame result = frame("\r\n\r\nGET / HTTP/1.1\r\nHost: a\r\n\r\n");
  ASSERT_EQ(result.verdict, Verdict::complete);
  EXPECT_EQ(result.skipped_bytes, 4U);
  EXPECT_EQ(result.wire_bytes, 4U + 27U);
}

TEST(ClassifyRequest, ContentLengthWithTransferEncodingIsRejected) {
  expect_reject(
      "POST /x HTTP/1.1\r\nHost: a\r\nContent-Length: 5\r\nTransfer-Encoding: chunked\r\n\r\n",
      HttpFault::transfer_encoding_and_length);
  expect_reject(
      "POST /x HTTP/1.1\r\nHost: a\r\nTransfer-Encoding: chunked\r\nContent-Length: 5\r\n\r\n",
      HttpFault::transfer_encoding_and_length);
}

TEST(ClassifyRequest, TransferCodingOtherThanChunkedIsRejected) {
  for (const char* coding : {"xchunked", "gzip, chunked", "chunked, chunked", "chunked;q=1", ""}) {
    expect_reject(std::string("POST /x HTTP/1.1\r\nHost: a\r\nTransfer-Encoding: ") + coding +
                      "\r\n\r\n0\r\n\r\n",
                  HttpFault::unsupported_transfer_coding);
  }
  expect_reject(
      "POST /x HTTP/1.1\r\nHost: a\r\nTransfer-Encoding: xchunked\r\nContent-Length: 3"
      "\r\n\r\nabc",
      HttpFault::transfer_encoding_and_length);
  EXPECT_EQ(
      frame("POST /x HTTP/1.1\r\nHost: a\r\nTransfer-Encoding: ChUnKeD\r\n\r\n0\r\n\r\n").verdict,
      Verdict::complete);
}

TEST(ClassifyRequest, TransferEncodingInHttp10IsRejected) {
  expect_reject("POST /x HTTP/1.0\r\nTransfer-Encoding: chunked\r\n\r\n0\r\n\r\n",
                HttpFault::transfer_encoding_in_http_one_zero);
}

TEST(ClassifyRequest, DifferingOrNonDigitContentLengthsAreRejected) {
  for (const char* lengths : {"Content-Length: 2\r\nContent-Length: 3", "Content-Length: +2",
                              "Content-Length: 2, 3", "Content-Length: -1", "Content-Length: 0x2",
                              "Content-Length: ", "Content-Length: 2 2", "Content-Length: 1e1"}) {
    expect_reject(std::string("POST /x HTTP/1.1\r\nHost: a\r\n") + lengths + "\r\n\r\n{}",
                  HttpFault::malformed_content_length);
  }
}

TEST(ClassifyRequest, RepeatedEqualContentLengthsAreOneLength) {
  const RequestFrame result =
      frame("POST /x HTTP/1.1\r\nHost: a\r\nContent-Length: 2\r\nContent-Length: 2, 2\r\n\r\n{}");
  ASSERT_EQ(result.verdict, Verdict::complete);
  EXPECT_EQ(result.body_bytes, 2U);
}

TEST(ClassifyRequest, BodyOverTheLimitIsRejectedBeforeItArrives) {
  expect_reject("POST /x HTTP/1.1\r\nHost: a\r\nContent-Length: 65537\r\n\r\n",
                HttpFault::body_too_large);
  expect_reject("POST /x HTTP/1.1\r\nHost: a\r\nContent-Length: 99999999999999999999999\r\n\r\n",
                HttpFault::body_too_large);
  expect_reject("POST /x HTTP/1.1\r\nHost: a\r\nTransfer-Encoding: chunked\r\n\r\n10001\r\n",
                HttpFault::body_too_large);
  const RequestFrame at_limit =
      frame("POST /x HTTP/1.1\r\nHost: a\r\nContent-Length: 65536\r\n\r\n");
  EXPECT_EQ(at_limit.verdict, Verdict::incomplete);
}

TEST(ClassifyRequest, ChunkedBodiesOverTheLimitInSumAreRejected) {
  std::string request = "POST /x HTTP/1.1\r\nHost: a\r\nTransfer-Encoding: chunked\r\n\r\n";
  const std::string chunk(0x8000, 'x');
  request += "8000\r\n" + chunk + "\r\n8000\r\n" + chunk + "\r\n";
  EXPECT_EQ(frame(request).verdict, Verdict::incomplete);  // exactly 64 KiB so far
  expect_reject(request + "1\r\n", HttpFault::body_too_large);
}

TEST(ClassifyRequest, BadChunkSizesAreRejected) {
  const std::string head = "POST /x HTTP/1.1\r\nHost: a\r\nTransfer-Encoding: chunked\r\n\r\n";
  for (const char* body :
       {"g\r\n", "\r\n", "-1\r\n", " 1\r\nx\r\n", "1 x\r\n", "0x1\r\n", "1\nx\r\n"}) {
    expect_reject(head + body, HttpFault::malformed_chunk_size);
  }
  expect_reject(head + "3\r\nabcX\r\n", HttpFault::chunk_without_crlf);
}

TEST(ClassifyRequest, ChunkExtensionsAndTrailersAreAccepted) {
  const std::string request =
      "POST /x HTTP/1.1\r\nHost: a\r\nTransfer-Encoding: chunked\r\n\r\n"
      "3;name=value\r\nabc\r\n2 ; x\r\nde\r\n0\r\nX-Checksum: 1\r\n\r\n";
  const RequestFrame result = frame(request + "GET");
  ASSERT_EQ(result.verdict, Verdict::complete);
  EXPECT_EQ(result.wire_bytes, request.size());
  EXPECT_EQ(result.body_bytes, 5U);
}

TEST(ClassifyRequest, MalformedHeadsAreRejected) {
  expect_reject("GET / HTTP/1.1\nHost: a\r\n\r\n", HttpFault::malformed_request_line);
  expect_reject("GET / HTTP/1.1\r\nHost: a\n\r\n", HttpFault::malformed_field_line);
  expect_reject("GET / HTTP/1.1\r\nHost: a\rb\r\n\r\n", HttpFault::malformed_field_line);
  expect_reject("GET / HTTP/1.1\r\nHost : a\r\n\r\n", HttpFault::malformed_field_line);
  expect_reject("GET / HTTP/1.1\r\nHost: a\r\n folded\r\n\r\n", HttpFault::malformed_field_line);
  expect_reject(std::string("GET / HTTP/1.1\r\nHost: a\0b\r\n\r\n", 29),
                HttpFault::malformed_field_line);
  expect_reject("GET / HTTP/1.1\r\nNo colon\r\n\r\n", HttpFault::malformed_field_line);
  expect_reject("GET  / HTTP/1.1\r\nHost: a\r\n\r\n", HttpFault::malformed_request_line);
  expect_reject("GET / HTTP/1.1 \r\nHost: a\r\n\r\n", HttpFault::malformed_request_line);
  expect_reject("GET /#frag HTTP/1.1\r\nHost: a\r\n\r\n", HttpFault::malformed_request_line);
  expect_reject("GET #x HTTP/1.1\r\nHost: a\r\n\r\n", HttpFault::malformed_request_line);
  expect_reject("GET / HTTP/2.0\r\nHost: a\r\n\r\n", HttpFault::unsupported_http_version);
  expect_reject("BREW / HTTP/1.1\r\nHost: a\r\n\r\n", HttpFault::unknown_method);
  expect_reject("garbage\r\n", HttpFault::malformed_request_line);
}

TEST(ClassifyRequest, Http11NeedsExactlyOneHost) {
  expect_reject("GET / HTTP/1.1\r\n\r\n", HttpFault::host_not_once);
  expect_reject("GET / HTTP/1.1\r\nHost: a\r\nHost: b\r\n\r\n", HttpFault::host_not_once);
  EXPECT_EQ(frame("GET / HTTP/1.0\r\n\r\n").verdict, Verdict::complete);
}

TEST(ClassifyRequest, OversizedHeadsAreRejectedWithoutWaitingForTheirEnd) {
  const std::string long_field = "GET / HTTP/1.1\r\nHost: a\r\nX: " + std::string(20000, 'x');
  expect_reject(long_field, HttpFault::head_too_large);
  expect_reject("GET /" + std::string(9000, 'a') + " HTTP/1.1\r\nHost: a\r\n\r\n",
                HttpFault::request_line_too_large);
  expect_reject("GET / HTTP/1.1\r\nHost: a\r\nX: " + std::string(9000, 'x') + "\r\n\r\n",
                HttpFault::field_line_too_large);
  std::string many = "GET / HTTP/1.1\r\nHost: a\r\n";
  for (int i = 0; i < 100; ++i) many += "X: 1\r\n";
  expect_reject(many + "\r\n", HttpFault::too_many_fields);
}

TEST(ClassifyRequest, ExpectContinueIsNotedForHttp11Only) {
  EXPECT_TRUE(frame("POST /x HTTP/1.1\r\nHost: a\r\nExpect: 100-Continue\r\nContent-Length: 2"
                    "\r\n\r\n")
                  .expects_continue);
  EXPECT_FALSE(frame("POST /x HTTP/1.0\r\nExpect: 100-continue\r\nContent-Length: 2\r\n\r\n")
                   .expects_continue);
}

// The request of a complete frame, from the same pass over the bytes.
struct Framed {
  RequestFrame frame;
  std::vector<HeaderField> fields;
  std::string decoded;
  std::string path_scratch;
  HttpRequest request;
};

Framed framed(std::string_view input) {
  Framed out;
  out.frame = classify_request(input, kLimits, &out.fields, &out.decoded);
  if (out.frame.verdict == Verdict::complete) {
    out.request = framed_request(input, out.frame, out.fields, out.decoded, out.path_scratch);
  }
  return out;
}

TEST(FramedRequest, ContentLengthBodyIsAViewOfTheInputUpToItsEnd) {
  const std::string input =
      "\r\nPOST /x?q=1 HTTP/1.1\r\nHost: a\r\nContent-Length: 2\r\n\r\n{}NEXT";
  const Framed result = framed(input);
  ASSERT_EQ(result.frame.verdict, Verdict::complete);
  EXPECT_EQ(result.request.method, "POST");
  EXPECT_EQ(result.request.target, "/x?q=1");
  EXPECT_EQ(result.request.path, "/x");
  EXPECT_TRUE(result.request.http11);
  EXPECT_EQ(result.request.body, "{}");
  EXPECT_GE(result.request.body.data(), input.data());  // no copy
  EXPECT_LT(result.request.body.data(), input.data() + input.size());
  ASSERT_EQ(result.fields.size(), 2U);
  EXPECT_EQ(result.request.header("content-length"), "2");
  EXPECT_EQ(result.request.header("HOST"), "a");
  EXPECT_EQ(result.request.header("Accept"), "");
}

TEST(FramedRequest, ChunkedBodyIsDecodedInTheFramingPass) {
  const std::string input =
      "POST /x HTTP/1.1\r\nHost: a\r\nTransfer-Encoding: chunked\r\nExpect: 100-continue\r\n"
      "Accept: */*\r\n\r\n2;e=1\r\n{\"\r\n3\r\na\":\r\n2\r\n1}\r\n0\r\nT: 1\r\n\r\nNEXT";
  const Framed result = framed(input);
  ASSERT_EQ(result.frame.verdict, Verdict::complete);
  EXPECT_EQ(result.request.body, "{\"a\":1}");
  EXPECT_EQ(result.request.header("accept"), "*/*");
  EXPECT_EQ(result.request.header("T"), "");  // trailer fields are not request fields
}

TEST(FramedRequest, PathIsPercentDecodedAndAbsoluteFormGivesItsPath) {
  EXPECT_EQ(framed("GET /health%7A HTTP/1.1\r\nHost: a\r\n\r\n").request.path, "/healthz");
  EXPECT_EQ(framed("GET /a+b%20c HTTP/1.1\r\nHost: a\r\n\r\n").request.path, "/a+b c");
  EXPECT_EQ(framed("GET http://cutcalc:8080/healthz?x HTTP/1.1\r\nHost: a\r\n\r\n").request.path,
            "/healthz");
  EXPECT_EQ(framed("GET http://cutcalc HTTP/1.1\r\nHost: a\r\n\r\n").request.path, "/");
}

TEST(FramedRequest, KeepAliveFollowsVersionAndConnectionTokens) {
  EXPECT_TRUE(framed("GET / HTTP/1.1\r\nHost: a\r\n\r\n").request.wants_keep_alive());
  EXPECT_FALSE(framed("GET / HTTP/1.1\r\nHost: a\r\nConnection: foo, Close\r\n\r\n")
                   .request.wants_keep_alive());
  EXPECT_FALSE(framed("GET / HTTP/1.0\r\n\r\n").request.wants_keep_alive());
  EXPECT_TRUE(
      framed("GET / HTTP/1.0\r\nConnection: keep-alive\r\n\r\n").request.wants_keep_alive());
}

TEST(FramedRequest, FieldsOfAnIncompleteRequestAreNotKeptFromAnEarlierCall) {
  std::vector<HeaderField> fields{{"stale", "x"}};
  std::string decoded = "stale";
  classify_request("GET / HTTP/1.1\r\nHo", kLimits, &fields, &decoded);
  EXPECT_TRUE(fields.empty());
  EXPECT_TRUE(decoded.empty());
}

}  // namespace
}  // namespace cutcalc::service
