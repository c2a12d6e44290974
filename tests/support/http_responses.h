#pragma once
// Reads the bytes a server sent on one connection back as HTTP/1.1 responses, strictly: the
// byte-level checks of the engine (tests/service, fuzz/http_engine_fuzzer.cpp) use it to tell a
// well-framed stream of responses from anything else.

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace cutcalc::testing {

struct HttpResponse {
  int status = 0;
  std::vector<std::pair<std::string, std::string>> headers;  // names lower-cased
  std::string body;

  // The value of the first field named `name` (lower case), or empty.
  [[nodiscard]] std::string header(std::string_view name) const;
  [[nodiscard]] std::size_t count(std::string_view name) const;
  [[nodiscard]] bool interim() const { return status >= 100 && status < 200; }
};

struct ParsedResponses {
  std::vector<HttpResponse> responses;  // interim (1xx) ones included, in order
  std::optional<std::string> error;     // what is not well-framed, from where parsing stopped

  [[nodiscard]] std::size_t finals() const;
};

// Whether the bytes are all the connection will carry: the server closed it after them.
enum class ConnectionState { open, closed };

// Every response is "HTTP/1.1 NNN reason" CRLF, field lines, CRLF; a final one carries exactly one
// Content-Length and no Transfer-Encoding, then that many bytes, or (a 200 written as it is sent)
// Transfer-Encoding: chunked alone and a whole chunked body, decoded into `body`, or (a 200
// written as it is sent to an HTTP/1.0 client) neither, with Connection: close, and the body is
// everything up to the close (RFC 9112 section 6.3, rule 8): only once the connection is closed.
// A response to HEAD has the Content-Length of the body it does not carry: a final response
// followed by nothing or by "HTTP/1.1 " is read as bodiless (no cutcalc body starts so).
ParsedResponses parse_responses(std::string_view bytes,
                                ConnectionState connection = ConnectionState::open);

}  // namespace cutcalc::testing
