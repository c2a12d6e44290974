#include "service/http_request.h"

#include "api/header_text.h"
#include "service/http_connection.h"
#include "service/httplib_adapter.h"

namespace cutcalc::service {

std::string_view HttpRequest::header(std::string_view name) const {
  for (const HeaderField& field : fields) {
    if (api::iequals_ascii(field.name, name)) return field.value;
  }
  return {};
}

bool HttpRequest::wants_keep_alive() const {
  // Connection is a list of tokens; "close" anywhere ends the connection, and HTTP/1.0 keeps it
  // only when asked to.
  bool close = false;
  bool keep_alive = false;
  for (const HeaderField& field : fields) {
    if (!api::iequals_ascii(field.name, "connection")) continue;
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
      close = close || api::iequals_ascii(token, "close");
      keep_alive = keep_alive || api::iequals_ascii(token, "keep-alive");
    }
  }
  return !close && (http11 || keep_alive);
}

std::string_view HttpRequest::remote_ip() const {
  return addresses == nullptr ? std::string_view{} : std::string_view(addresses->peer().ip);
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
