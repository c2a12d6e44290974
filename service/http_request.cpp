#include "service/http_request.h"

#include "domain/common/ascii_text.h"
#include "service/socket_addresses.h"

namespace cutcalc::service {
namespace {

// The value of the `digits` hex digits at `at`, or -1 when they are not all there.
int hex_value(std::string_view text, std::size_t at, std::size_t digits) {
  if (at + digits > text.size()) return -1;
  int value = 0;
  for (const char c : text.substr(at, digits)) {
    const int digit = c >= '0' && c <= '9'   ? c - '0'
                      : c >= 'a' && c <= 'f' ? c - 'a' + 10
                      : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                             : -1;
    if (digit < 0) return -1;
    value = value * 16 + digit;
  }
  return value;
}

// `code` (at most U+FFFF) as UTF-8; nothing for a surrogate, which is no character.
void append_utf8(int code, std::string& out) {
  const auto byte = [](int bits) { return static_cast<char>(bits); };
  if (code < 0x80) {
    out += byte(code);
  } else if (code < 0x800) {
    out += byte(0xC0 | (code >> 6));
    out += byte(0x80 | (code & 0x3F));
  } else if (code < 0xD800 || code >= 0xE000) {
    out += byte(0xE0 | (code >> 12));
    out += byte(0x80 | ((code >> 6) & 0x3F));
    out += byte(0x80 | (code & 0x3F));
  }
}

}  // namespace

std::string percent_decode_path(std::string_view path) {
  std::string decoded;
  decoded.reserve(path.size());
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (path[i] == '%' && i + 1 < path.size() && path[i + 1] == 'u') {
      if (const int code = hex_value(path, i + 2, 4); code >= 0) {
        append_utf8(code, decoded);
        i += 5;
        continue;
      }
    } else if (path[i] == '%') {
      if (const int byte = hex_value(path, i + 1, 2); byte >= 0) {
        decoded += static_cast<char>(byte);
        i += 2;
        continue;
      }
    }
    decoded += path[i];  // '+' included: it is not a space in a path
  }
  return decoded;
}

std::string_view HttpRequest::header(std::string_view name) const {
  for (const HeaderField& field : fields) {
    if (domain::iequals_ascii(field.name, name)) return field.value;
  }
  return {};
}

bool HttpRequest::wants_keep_alive() const {
  // Connection is a list of tokens; "close" anywhere ends the connection, and HTTP/1.0 keeps it
  // only when asked to.
  bool close = false;
  bool keep_alive = false;
  for (const HeaderField& field : fields) {
    if (!domain::iequals_ascii(field.name, "connection")) continue;
    std::string_view rest = field.value;
    while (!rest.empty()) {
      const std::size_t comma = rest.find(',');
      std::string_view token = rest.substr(0, comma);
      rest = comma == std::string_view::npos ? std::string_view{} : rest.substr(comma + 1);
      while (!token.empty() && (token.front() == ' ' || token.front() == '\t')) {
        token.remove_prefix(1);
      }
      while (!token.empty() && (token.back() == ' ' || token.back() == '\t')) {
        token.remove_suffix(1);
      }
      close = close || domain::iequals_ascii(token, "close");
      keep_alive = keep_alive || domain::iequals_ascii(token, "keep-alive");
    }
  }
  return !close && (http11 || keep_alive);
}

std::string_view HttpRequest::remote_ip() const {
  return addresses == nullptr ? std::string_view{} : std::string_view(addresses->peer().ip);
}

OwnedRequest::OwnedRequest(const HttpRequest& request) : body_(request.body) {
  std::size_t head_bytes = request.method.size() + request.target.size() + request.path.size();
  for (const HeaderField& field : request.fields)
    head_bytes += field.name.size() + field.value.size();
  head_.reserve(head_bytes);  // no reallocation below: the views stay valid
  const auto keep = [this](std::string_view text) {
    const std::size_t at = head_.size();
    head_.append(text);
    return std::string_view(head_).substr(at, text.size());
  };
  request_.method = keep(request.method);
  request_.target = keep(request.target);
  request_.path = keep(request.path);
  fields_.reserve(request.fields.size());
  for (const HeaderField& field : request.fields) {
    const std::string_view name = keep(field.name);
    fields_.push_back({name, keep(field.value)});
  }
  request_.http11 = request.http11;
  request_.fields = fields_;
  request_.body = body_;
  request_.phase = request.phase;
}

std::string_view request_path(std::string_view target, std::string& scratch) {
  if (!target.empty() && target.front() != '/' && target != "*") {
    // absolute-form: scheme "://" authority path
    const std::size_t authority = target.find("://");
    const std::size_t slash =
        authority == std::string_view::npos ? authority : target.find('/', authority + 3);
    target = slash == std::string_view::npos ? std::string_view("/") : target.substr(slash);
  }
  const std::string_view path = target.substr(0, target.find('?'));
  if (path.find('%') == std::string_view::npos) return path;
  scratch = percent_decode_path(path);
  return scratch;
}

}  // namespace cutcalc::service
