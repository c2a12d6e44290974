#include "service/http_response.h"

#include <charconv>

namespace cutcalc::service {
namespace {

void append_number(std::string& out, std::size_t value) {
  char digits[24];
  const auto result = std::to_chars(digits, digits + sizeof(digits), value);
  out.append(digits, result.ptr);
}

}  // namespace

bool HttpResponse::has_header(std::string_view name) const {
  for (const ResponseHeader& header : headers) {
    if (header.name == name) return true;
  }
  return false;
}

std::string_view HttpResponse::header(std::string_view name) const {
  for (const ResponseHeader& header : headers) {
    if (header.name == name) return header.value;
  }
  return {};
}

// RFC 9110 section 15 names.
std::string_view reason_phrase(int status) {
  switch (status) {
    case 100:
      return "Continue";
    case 200:
      return "OK";
    case 204:
      return "No Content";
    case 400:
      return "Bad Request";
    case 404:
      return "Not Found";
    case 405:
      return "Method Not Allowed";
    case 406:
      return "Not Acceptable";
    case 413:
      return "Content Too Large";
    case 415:
      return "Unsupported Media Type";
    case 422:
      return "Unprocessable Content";
    case 500:
      return "Internal Server Error";
    case 503:
      return "Service Unavailable";
    default:
      return "Unknown";
  }
}

void write_response(const HttpResponse& response, bool head_only, ConnectionAfter after,
                    std::string& out, bool http11) {
  const bool no_content = response.status == 204 || response.status < 200;
  out.reserve(out.size() + 256 + (head_only ? 0 : response.body.size()));
  out.append("HTTP/1.1 ");
  append_number(out, static_cast<std::size_t>(response.status));
  out.push_back(' ');
  out.append(reason_phrase(response.status));
  out.append("\r\n");
  if (!response.content_type.empty()) {
    out.append("Content-Type: ").append(response.content_type).append("\r\n");
  }
  if (response.body_source) {
    if (http11) out.append("Transfer-Encoding: chunked\r\n");
  } else if (!no_content) {
    out.append("Content-Length: ");
    append_number(out, response.body.size());
    out.append("\r\n");
  }
  for (const ResponseHeader& header : response.headers) {
    out.append(header.name).append(": ").append(header.value).append("\r\n");
  }
  if (after == ConnectionAfter::close) {
    out.append("Connection: close\r\n");
  } else if (after == ConnectionAfter::keep_alive_http10) {
    out.append("Connection: keep-alive\r\n");
  }
  out.append("\r\n");
  if (!head_only && !no_content && !response.body_source) out.append(response.body);
}

void append_body_piece(std::string_view piece, bool chunked, std::string& out) {
  if (piece.empty()) return;
  if (chunked) {
    char digits[20];
    const auto result = std::to_chars(digits, digits + sizeof(digits), piece.size(), 16);
    out.append(digits, result.ptr).append("\r\n");
  }
  out.append(piece);
  if (chunked) out.append("\r\n");
}

void end_body(bool chunked, std::string& out) {
  if (chunked) out.append("0\r\n\r\n");
}

}  // namespace cutcalc::service
