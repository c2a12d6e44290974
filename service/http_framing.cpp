#include "service/http_framing.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "domain/common/ascii_text.h"

namespace cutcalc::service {
namespace {

using Verdict = RequestFrame::Verdict;
constexpr std::size_t npos = std::string_view::npos;

// Content-Length values are parsed saturating here (far above any body limit).
constexpr std::uint64_t kLengthCap = std::uint64_t{1} << 62;

// Character classes of RFC 9110 5.6.2 (tchar) and 5.5 (field-value: VCHAR, obs-text, SP, HTAB),
// as tables: the framing runs on every request.
struct CharClasses {
  std::array<bool, 256> tchar{};
  std::array<bool, 256> field_value{};
  constexpr CharClasses() {
    for (int c = 0; c < 256; ++c) {
      const bool alnum = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
      tchar[c] = alnum || std::string_view("!#$%&'*+-.^_`|~").find(static_cast<char>(c)) != npos;
      field_value[c] = c == ' ' || c == '\t' || (c >= 0x21 && c != 0x7f);
    }
  }
};
constexpr CharClasses kClasses;

bool is_tchar(char c) { return kClasses.tchar[static_cast<unsigned char>(c)]; }

bool is_token(std::string_view text) {
  return !text.empty() && std::all_of(text.begin(), text.end(), is_tchar);
}

bool is_field_value(std::string_view text) {
  return std::all_of(text.begin(), text.end(),
                     [](char c) { return kClasses.field_value[static_cast<unsigned char>(c)]; });
}

// The methods of RFC 9110 (and PATCH, PRI); others are refused before any handler sees them.
bool is_known_method(std::string_view method) {
  for (const std::string_view known :
       {"GET", "HEAD", "POST", "PUT", "DELETE", "CONNECT", "OPTIONS", "TRACE", "PATCH", "PRI"}) {
    if (method == known) return true;
  }
  return false;
}

bool is_blank(char c) { return c == ' ' || c == '\t'; }

std::string_view trim(std::string_view text) {
  while (!text.empty() && is_blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_blank(text.back())) text.remove_suffix(1);
  return text;
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

enum class Line { ok, incomplete, bad };

// The CRLF-terminated line at `pos` (without its CRLF). A line is bad when its LF has no CR before
// it, or it holds a CR or NUL of its own.
Line next_line(std::string_view input, std::size_t pos, std::string_view& line) {
  const std::size_t lf = input.find('\n', pos);
  if (lf == npos) {
    const std::string_view partial = input.substr(pos);
    const std::size_t cr = partial.find('\r');
    // A CR that is not the last byte must be followed by LF, which it is not.
    if ((cr != npos && cr + 1 < partial.size()) || partial.find('\0') != npos) return Line::bad;
    return Line::incomplete;
  }
  if (lf == pos || input[lf - 1] != '\r') return Line::bad;
  line = input.substr(pos, lf - 1 - pos);
  if (line.find('\r') != npos || line.find('\0') != npos) return Line::bad;
  return Line::ok;
}

RequestFrame reject(RequestFrame frame, HttpFault fault) {
  frame.verdict = Verdict::reject;
  frame.fault = fault;
  return frame;
}

// A field line: name ":" OWS value OWS (RFC 9112 5.1); no obs-fold, no space before the colon.
bool split_field(std::string_view line, std::string_view& name, std::string_view& value) {
  const std::size_t colon = line.find(':');
  if (colon == npos) return false;
  name = line.substr(0, colon);
  value = trim(line.substr(colon + 1));
  return is_token(name) && is_field_value(value);
}

// "42" or "42, 42": every element all digits and the same (RFC 9110 8.6). False otherwise.
bool parse_content_length(std::string_view value, bool& seen, std::uint64_t& length) {
  do {
    const std::size_t comma = value.find(',');
    const std::string_view element = trim(value.substr(0, comma));
    value = comma == npos ? std::string_view{} : value.substr(comma + 1);
    if (element.empty()) return false;
    std::uint64_t parsed = 0;
    for (const char c : element) {
      if (c < '0' || c > '9') return false;
      parsed = std::min(parsed * 10 + static_cast<std::uint64_t>(c - '0'), kLengthCap);
    }
    if (seen && parsed != length) return false;
    seen = true;
    length = parsed;
  } while (!value.empty());
  return true;
}

// Walks a chunked body from `pos` (RFC 9112 7.1). Sets the frame's wire and body sizes when the
// last chunk and the trailer section are in; `decoded`, when given, receives the content.
RequestFrame frame_chunked(std::string_view input, std::size_t pos, RequestFrame frame,
                           const HttpLimits& limits, std::size_t body_limit, std::string* decoded) {
  std::size_t framing = 0;  // chunk sizes, extensions, CRLFs and trailers
  std::size_t content = 0;
  std::size_t fields = 0;
  // The next framing line at `pos`, counted against the head's allowance: ok, or a verdict.
  const auto framing_line = [&](std::string_view& line,
                                HttpFault malformed) -> std::optional<RequestFrame> {
    switch (next_line(input, pos, line)) {
      case Line::bad:
        return reject(frame, malformed);
      case Line::incomplete:
        if (framing + (input.size() - pos) > limits.max_head_bytes) {
          return reject(frame, HttpFault::chunk_framing_too_large);
        }
        return frame;
      case Line::ok:
        break;
    }
    framing += line.size() + 2;
    pos += line.size() + 2;
    if (framing > limits.max_head_bytes) return reject(frame, HttpFault::chunk_framing_too_large);
    return std::nullopt;
  };
  for (;;) {
    std::string_view line;
    if (auto verdict = framing_line(line, HttpFault::malformed_chunk_size)) return *verdict;
    // chunk-size [ chunk-ext ]: 1*HEXDIG, then nothing or BWS ";" and the extension (ignored).
    std::size_t digits = 0;
    std::uint64_t size = 0;
    while (digits < line.size() && hex_digit(line[digits]) >= 0) {
      size = std::min(size * 16 + static_cast<std::uint64_t>(hex_digit(line[digits])), kLengthCap);
      ++digits;
    }
    const std::string_view rest = trim(line.substr(digits));
    if (digits == 0 || (!rest.empty() && (rest.front() != ';' || !is_field_value(rest)))) {
      return reject(frame, HttpFault::malformed_chunk_size);
    }
    if (size > body_limit - content) {
      return reject(frame, HttpFault::body_too_large);
    }
    if (size == 0) break;
    if (input.size() - pos < size + 2) return frame;
    if (input.substr(pos + size, 2) != "\r\n") {
      return reject(frame, HttpFault::chunk_without_crlf);
    }
    if (decoded != nullptr) decoded->append(input.substr(pos, size));
    content += size;
    pos += size + 2;
    framing += 2;
  }
  // Trailer section: field lines (validated, then dropped), then an empty line.
  for (;;) {
    std::string_view line;
    if (auto verdict = framing_line(line, HttpFault::malformed_trailer_field)) return *verdict;
    if (line.empty()) break;
    std::string_view name;
    std::string_view value;
    if (!split_field(line, name, value) || ++fields > limits.max_fields) {
      return reject(frame, HttpFault::malformed_trailer_field);
    }
  }
  frame.verdict = Verdict::complete;
  frame.wire_bytes = pos;
  frame.body_bytes = content;
  return frame;
}

}  // namespace

RequestFrame classify_request(std::string_view input, const HttpLimits& limits,
                              std::vector<HeaderField>* fields_out, std::string* decoded_body) {
  RequestFrame frame;
  if (fields_out != nullptr) fields_out->clear();
  if (decoded_body != nullptr) decoded_body->clear();
  std::size_t pos = 0;
  // Empty lines before the request line are ignored (RFC 9112 2.2).
  while (input.substr(pos, 2) == "\r\n") pos += 2;
  if (pos > limits.max_head_bytes) {
    return reject(frame, HttpFault::too_many_empty_lines);
  }
  frame.skipped_bytes = pos;
  const std::size_t start = pos;
  // The next line of the head at `pos`: ok, or the verdict (incomplete, or a rejection).
  const auto head_line = [&](std::string_view& line,
                             HttpFault malformed) -> std::optional<RequestFrame> {
    switch (next_line(input, pos, line)) {
      case Line::bad:
        return reject(frame, malformed);
      case Line::incomplete:
        if (input.size() - start > limits.max_head_bytes)
          return reject(frame, HttpFault::head_too_large);
        return frame;
      case Line::ok:
        break;
    }
    pos += line.size() + 2;
    if (pos - start > limits.max_head_bytes) return reject(frame, HttpFault::head_too_large);
    return std::nullopt;
  };

  // request-line = method SP request-target SP HTTP-version (RFC 9112 3)
  std::string_view request_line;
  if (auto verdict = head_line(request_line, HttpFault::malformed_request_line)) return *verdict;
  const std::size_t space1 = request_line.find(' ');
  const std::size_t space2 = space1 == npos ? npos : request_line.find(' ', space1 + 1);
  if (space2 == npos || space2 == space1 + 1 || request_line.find(' ', space2 + 1) != npos) {
    return reject(frame, HttpFault::malformed_request_line);
  }
  const std::string_view method = request_line.substr(0, space1);
  const std::string_view target = request_line.substr(space1 + 1, space2 - space1 - 1);
  const std::string_view version = request_line.substr(space2 + 1);
  // origin-form, absolute-form or asterisk-form (RFC 9112 3.2), visible ASCII, no fragment.
  const bool target_ok = (target.front() == '/' || target == "*" ||
                          domain::iequals_ascii(target.substr(0, 7), "http://") ||
                          domain::iequals_ascii(target.substr(0, 8), "https://")) &&
                         std::all_of(target.begin(), target.end(),
                                     [](char c) { return c > 0x20 && c < 0x7f && c != '#'; });
  if (!is_token(method) || !target_ok) return reject(frame, HttpFault::malformed_request_line);
  if (request_line.size() > limits.max_request_line_bytes) {
    return reject(frame, HttpFault::request_line_too_large);
  }
  frame.method = method;
  frame.target = target;
  if (!is_known_method(method)) return reject(frame, HttpFault::unknown_method);
  const bool http11 = version == "HTTP/1.1";
  if (!http11 && version != "HTTP/1.0") {
    return reject(frame, HttpFault::unsupported_http_version);
  }
  frame.http11 = http11;

  // field lines, up to the empty line
  std::size_t fields = 0;
  std::size_t hosts = 0;
  bool has_length = false;
  std::uint64_t length = 0;
  bool has_transfer_encoding = false;
  std::size_t codings = 0;
  bool only_chunked = true;
  for (;;) {
    std::string_view line;
    if (auto verdict = head_line(line, HttpFault::malformed_field_line)) return *verdict;
    if (line.empty()) break;
    std::string_view name;
    std::string_view value;
    if (!split_field(line, name, value)) return reject(frame, HttpFault::malformed_field_line);
    if (line.size() > limits.max_field_line_bytes) {
      return reject(frame, HttpFault::field_line_too_large);
    }
    if (++fields > limits.max_fields) return reject(frame, HttpFault::too_many_fields);
    if (fields_out != nullptr) fields_out->push_back({name, value});
    if (domain::iequals_ascii(name, "content-length")) {
      if (!parse_content_length(value, has_length, length)) {
        return reject(frame, HttpFault::malformed_content_length);
      }
    } else if (domain::iequals_ascii(name, "transfer-encoding")) {
      has_transfer_encoding = true;
      std::string_view rest = value;
      do {
        const std::size_t comma = rest.find(',');
        const std::string_view coding = trim(rest.substr(0, comma));
        rest = comma == npos ? std::string_view{} : rest.substr(comma + 1);
        if (coding.empty()) continue;
        ++codings;
        only_chunked = only_chunked && domain::iequals_ascii(coding, "chunked");
      } while (!rest.empty());
    } else if (domain::iequals_ascii(name, "host")) {
      ++hosts;
    } else if (domain::iequals_ascii(name, "origin")) {
      frame.origin = value;
    } else if (domain::iequals_ascii(name, "accept-language")) {
      frame.accept_language = value;
    } else if (domain::iequals_ascii(name, "expect")) {
      frame.expects_continue =
          frame.expects_continue || (http11 && domain::iequals_ascii(value, "100-continue"));
    }
  }
  frame.head_bytes = pos - start;
  frame.body_offset = pos;

  if (http11 ? hosts != 1 : hosts > 1) {
    return reject(frame, HttpFault::host_not_once);
  }
  if (has_transfer_encoding) {
    if (has_length) return reject(frame, HttpFault::transfer_encoding_and_length);
    if (!http11) return reject(frame, HttpFault::transfer_encoding_in_http_one_zero);
    if (codings != 1 || !only_chunked) {
      return reject(frame, HttpFault::unsupported_transfer_coding);
    }
    frame.chunked = true;
    return frame_chunked(input, pos, frame, limits, limits.body_limit_for(frame.target),
                         decoded_body);
  }
  if (length > limits.body_limit_for(frame.target)) {
    return reject(frame, HttpFault::body_too_large);
  }
  frame.body_bytes = static_cast<std::size_t>(length);
  if (input.size() - pos < frame.body_bytes) return frame;
  frame.verdict = Verdict::complete;
  frame.wire_bytes = pos + frame.body_bytes;
  return frame;
}

HttpRequest framed_request(std::string_view input, const RequestFrame& frame,
                           std::span<const HeaderField> fields, std::string_view decoded_body,
                           std::string& path_scratch) {
  HttpRequest request;
  request.method = frame.method;
  request.target = frame.target;
  request.path = request_path(frame.target, path_scratch);
  request.http11 = frame.http11;
  request.fields = fields;
  request.body = frame.chunked ? decoded_body : input.substr(frame.body_offset, frame.body_bytes);
  return request;
}

}  // namespace cutcalc::service
