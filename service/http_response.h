#pragma once
// A response as the app builds it, and its bytes on the wire (RFC 9112 4-6): the engine writes
// every response, its framing (Content-Length, Connection) included, in one place.

#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "domain/common/text_source.h"

namespace cutcalc::service {

struct ResponseHeader {
  std::string name;
  std::string value;
};

struct HttpResponse {
  int status = 200;
  std::string content_type;  // empty: no body is described (e.g. 204)
  std::string body;
  std::vector<ResponseHeader> headers;  // besides Content-Type, Content-Length and Connection
  // A body written as it is sent, instead of `body` (a program of many megabytes): framed chunked
  // (HTTP/1.1) or by the connection's close (HTTP/1.0), written piece by piece as the client reads.
  std::shared_ptr<domain::TextSource> body_source;

  void set_header(std::string_view name, std::string value) {
    headers.push_back({std::string(name), std::move(value)});
  }
  [[nodiscard]] bool has_header(std::string_view name) const;
  // The value of the first header named exactly `name`, or empty.
  [[nodiscard]] std::string_view header(std::string_view name) const;
  void set_content(std::string content, std::string type) {
    body = std::move(content);
    content_type = std::move(type);
  }
};

// How the connection goes on after a response.
enum class ConnectionAfter {
  keep_alive,         // HTTP/1.1: nothing said
  keep_alive_http10,  // HTTP/1.0 asked for keep-alive: Connection: keep-alive
  close               // Connection: close
};

// Appends `response` to `out`: status line, headers, Content-Length (none on 1xx/204), Connection
// when it says something, and the body unless `head_only` (a HEAD request: the GET answer's
// headers, Content-Length included, without the body). A response with a body_source gets
// Transfer-Encoding: chunked when `http11`, else no length (its caller closes after it), and no
// body here: the engine writes its pieces (append_body_piece, end_body).
void write_response(const HttpResponse& response, bool head_only, ConnectionAfter after,
                    std::string& out, bool http11 = true);

// One piece of a body_source, framed as a chunk (`chunked`) or as it is; an empty piece writes
// nothing (a zero-size chunk would end the body).
void append_body_piece(std::string_view piece, bool chunked, std::string& out);
// The end of a body_source's body: the last chunk (`chunked`, no trailer), else nothing.
void end_body(bool chunked, std::string& out);

// The reason phrase of a status the service sends ("OK", "Not Found", ...).
std::string_view reason_phrase(int status);

}  // namespace cutcalc::service
