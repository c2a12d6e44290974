#pragma once
// Request framing (RFC 9112 sections 2-7): where one request ends and the next begins on a
// connection, and the request itself (method, target, fields, body), in the same single pass over
// its bytes. The engine consumes exactly `wire_bytes` after answering, so no response or error can
// leave an unread body to be taken for the next request.
//
// Strict where framing is at stake, as RFC 9112 asks of a server that may sit behind a proxy:
//  - every line of the head ends in CRLF; a bare CR or LF, a NUL, obs-fold, whitespace before a
//    field's colon or an invalid field name is a 400;
//  - Transfer-Encoding with Content-Length, a coding other than exactly `chunked`, or
//    Transfer-Encoding in HTTP/1.0: 400 (section 6.1, 6.3);
//  - Content-Length values that are not all digits or that differ: 400 (section 6.3);
//  - a bad chunk size or chunk framing: 400 (section 7.1);
//  - an HTTP/1.1 request without exactly one Host: 400 (section 3.2);
//  - a method outside the known set, or a line over the limit: 400;
//  - a body over the limit (declared, or as it arrives chunked): 413.
// Every rejection ends the connection after its response.

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "service/http_request.h"

#include "service/http_fault.h"
#include "service/http_limits.h"

namespace cutcalc::service {

struct RequestFrame {
  enum class Verdict { incomplete, complete, reject };
  Verdict verdict = Verdict::incomplete;

  // complete (and, where known, incomplete and reject):
  std::size_t skipped_bytes = 0;  // empty lines before the request line (section 2.2)
  std::size_t head_bytes = 0;     // request line, fields and the empty line; 0 until complete
  std::size_t wire_bytes = 0;     // everything the request occupies on the wire, skipped included
  std::size_t body_bytes = 0;     // content length (chunked: decoded)
  bool chunked = false;
  bool expects_continue = false;  // Expect: 100-continue (HTTP/1.1)
  std::string_view method;        // from the request line, once it is complete and valid
  std::string_view target;
  std::string_view origin;  // the Origin field, once read (CORS headers on a rejection too)
  std::string_view accept_language;  // the Accept-Language field, once read (a rejection's too)
  bool http11 = true;                // false: HTTP/1.0
  std::size_t body_offset = 0;       // where the body starts in the input (after the head)

  // reject:
  HttpFault fault = HttpFault::malformed_request_line;
};

// Frames the request at the start of `input` (unread bytes of a connection). When given,
// `fields` receives the header fields (views of `input`) and `decoded_body` a chunked body's
// content; both are cleared first and complete only when the verdict is `complete`.
RequestFrame classify_request(std::string_view input, const HttpLimits& limits,
                              std::vector<HeaderField>* fields = nullptr,
                              std::string* decoded_body = nullptr);

// The request of a complete frame: views of `input`, `fields` and `decoded_body` (the outputs of
// classify_request), and of `path_scratch` when the path needed percent-decoding.
HttpRequest framed_request(std::string_view input, const RequestFrame& frame,
                           std::span<const HeaderField> fields, std::string_view decoded_body,
                           std::string& path_scratch);

}  // namespace cutcalc::service
