#include "support/http_responses.h"

#include <algorithm>
#include <cctype>

namespace cutcalc::testing {
namespace {

constexpr std::string_view kVersion = "HTTP/1.1 ";

std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

bool all_digits(std::string_view text) {
  return !text.empty() && std::all_of(text.begin(), text.end(),
                                      [](unsigned char c) { return std::isdigit(c) != 0; });
}

}  // namespace

std::string HttpResponse::header(std::string_view name) const {
  for (const auto& [key, value] : headers) {
    if (key == name) return value;
  }
  return {};
}

std::size_t HttpResponse::count(std::string_view name) const {
  return static_cast<std::size_t>(std::count_if(
      headers.begin(), headers.end(), [&](const auto& field) { return field.first == name; }));
}

std::size_t ParsedResponses::finals() const {
  return static_cast<std::size_t>(std::count_if(
      responses.begin(), responses.end(), [](const HttpResponse& r) { return !r.interim(); }));
}

ParsedResponses parse_responses(std::string_view bytes, ConnectionState connection) {
  ParsedResponses parsed;
  const auto fail = [&](std::string what) {
    parsed.error = what + " (response " + std::to_string(parsed.responses.size() + 1) + ")";
    return parsed;
  };
  while (!bytes.empty()) {
    const std::size_t head_end = bytes.find("\r\n\r\n");
    if (head_end == std::string_view::npos) return fail("truncated response head");
    const std::string_view head = bytes.substr(0, head_end + 2);
    bytes.remove_prefix(head_end + 4);

    HttpResponse response;
    std::size_t line_end = head.find("\r\n");
    const std::string_view status_line = head.substr(0, line_end);
    if (status_line.substr(0, kVersion.size()) != kVersion || status_line.size() < 13 ||
        !all_digits(status_line.substr(9, 3)) || status_line[12] != ' ') {
      return fail("bad status line '" + std::string(status_line.substr(0, 40)) + "'");
    }
    response.status = std::stoi(std::string(status_line.substr(9, 3)));
    if (response.status < 100) return fail("bad status code");
    std::size_t pos = line_end + 2;
    while (pos < head.size()) {
      line_end = head.find("\r\n", pos);
      const std::string_view line = head.substr(pos, line_end - pos);
      pos = line_end + 2;
      const std::size_t colon = line.find(':');
      if (colon == std::string_view::npos || colon == 0 || line.find_first_of(" \t") < colon) {
        return fail("bad header line '" + std::string(line.substr(0, 40)) + "'");
      }
      std::string_view value = line.substr(colon + 1);
      while (!value.empty() && (value.front() == ' ' || value.front() == '\t')) {
        value.remove_prefix(1);
      }
      response.headers.emplace_back(lower(line.substr(0, colon)), std::string(value));
    }
    if (response.interim()) {
      if (response.status != 100 || !response.headers.empty()) return fail("unexpected 1xx");
      parsed.responses.push_back(std::move(response));
      continue;
    }
    if (response.count("transfer-encoding") != 0) {
      // A body written as it is sent: exactly "chunked", no Content-Length, chunks of lower-case
      // hex sizes without extensions, the last one empty, no trailer.
      if (response.count("transfer-encoding") != 1 ||
          response.header("transfer-encoding") != "chunked" ||
          response.count("content-length") != 0 || response.status != 200) {
        return fail("a Transfer-Encoding other than one chunked 200 without Content-Length");
      }
      for (;;) {
        const std::size_t size_end = bytes.find("\r\n");
        if (size_end == std::string_view::npos) return fail("truncated chunked body");
        const std::string_view size_text = bytes.substr(0, size_end);
        if (size_text.empty() || size_text.size() > 8 ||
            size_text.find_first_not_of("0123456789abcdef") != std::string_view::npos ||
            (size_text.size() > 1 && size_text.front() == '0')) {
          return fail("bad chunk size '" + std::string(size_text.substr(0, 20)) + "'");
        }
        const std::size_t size = std::stoul(std::string(size_text), nullptr, 16);
        bytes.remove_prefix(size_end + 2);
        if (size == 0) {
          if (bytes.substr(0, 2) != "\r\n") return fail("truncated chunked body end");
          bytes.remove_prefix(2);
          break;
        }
        if (bytes.size() < size + 2) return fail("truncated chunked body");
        if (bytes.substr(size, 2) != "\r\n") return fail("a chunk not followed by CRLF");
        response.body.append(bytes.substr(0, size));
        bytes.remove_prefix(size + 2);
      }
      parsed.responses.push_back(std::move(response));
      continue;
    }
    if (response.status == 204) {  // no content, and no Content-Length (RFC 9110 8.6)
      if (response.count("content-length") != 0) return fail("Content-Length in a 204");
      parsed.responses.push_back(std::move(response));
      continue;
    }
    if (response.count("content-length") == 0 && response.status == 200 &&
        lower(response.header("connection")) == "close") {
      if (connection == ConnectionState::open)
        return fail("a body up to the close, not closed yet");
      response.body = std::string(bytes);
      parsed.responses.push_back(std::move(response));
      return parsed;
    }
    if (response.count("content-length") != 1 || !all_digits(response.header("content-length"))) {
      return fail("not exactly one numeric Content-Length");
    }
    const std::size_t length = std::stoul(response.header("content-length"));
    const bool bodiless =
        length > 0 && (bytes.empty() || bytes.substr(0, kVersion.size()) == kVersion);
    if (!bodiless) {
      if (bytes.size() < length) return fail("truncated body");
      response.body = std::string(bytes.substr(0, length));
      bytes.remove_prefix(length);
    }
    parsed.responses.push_back(std::move(response));
  }
  return parsed;
}

}  // namespace cutcalc::testing
