#pragma once
// Request framing (RFC 9112 sections 2-7): where one request ends and the next begins on a
// connection. The engine decides this here, once, before the HTTP library sees a byte; the library
// then parses only a request that is already framed (library_request()), and the engine consumes
// exactly `wire_bytes` afterwards, whatever the library read. So no response, error or quirk of the
// library can leave an unread body to be taken for the next request.
//
// Strict where framing is at stake, as RFC 9112 asks of a server that may sit behind a proxy:
//  - every line of the head ends in CRLF; a bare CR or LF, a NUL, obs-fold, whitespace before a
//    field's colon or an invalid field name is a 400;
//  - Transfer-Encoding with Content-Length, a coding other than exactly `chunked`, or
//    Transfer-Encoding in HTTP/1.0: 400 (section 6.1, 6.3);
//  - Content-Length values that are not all digits or that differ: 400 (section 6.3);
//  - a bad chunk size or chunk framing: 400 (section 7.1);
//  - an HTTP/1.1 request without exactly one Host: 400 (section 3.2);
//  - a method the HTTP library does not implement, or a line longer than it reads: 400;
//  - a body over the limit (declared, or as it arrives chunked): 413.
// Every rejection ends the connection after its response.

#include <cstddef>
#include <string>
#include <string_view>

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

  // reject:
  int status = 0;           // 400 or 413
  std::string_view reason;  // a fixed sentence for the problem's detail
};

// Frames the request at the start of `input` (unread bytes of a connection).
RequestFrame classify_request(std::string_view input, const HttpLimits& limits);

// The bytes the HTTP library is to parse for a complete frame: a view of `input` when the request
// can be read as it came (Content-Length or no body, no Expect), otherwise the request rewritten
// into `scratch` with its body decoded and a Content-Length in place of Transfer-Encoding, and
// without Expect (the engine answers 100-continue itself, so the library must not again).
std::string_view library_request(std::string_view input, const RequestFrame& frame,
                                 std::string& scratch);

}  // namespace cutcalc::service
