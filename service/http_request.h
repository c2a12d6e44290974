#pragma once
// One HTTP request as the engine framed it (service/http_framing.h): parsed once, handed to the
// app as a value. Every view points into the connection's buffers and is valid only during the
// call that receives the request; work that outlives it copies what it needs.

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace cutcalc::service {

class SocketAddresses;

struct HeaderField {
  std::string_view name;   // as sent (compare case-insensitively)
  std::string_view value;  // without surrounding whitespace
};

// Where the server is in its life (README.md, "Restarts"):
enum class ServerPhase {
  serving,   // keep-alive as usual
  draining,  // SIGTERM, lame duck: the listener accepts still; every response says close
  stopped    // the listener is closed: idle connections close after the drain grace
};

struct HttpRequest {
  std::string_view method;
  std::string_view target;  // as sent
  std::string_view path;    // the target's path, percent-decoded (request_path())
  bool http11 = true;       // false: HTTP/1.0
  std::span<const HeaderField> fields;
  std::string_view body;                       // the content (a chunked body decoded)
  const SocketAddresses* addresses = nullptr;  // of the connection; null in unit tests
  // The server's phase when the engine framed the request, read once: the engine's keep-alive
  // decision and the app's answer (/readyz) both use this one snapshot, so a SIGTERM between them
  // cannot make them disagree.
  ServerPhase phase = ServerPhase::serving;

  // The value of the first field named `name` (case-insensitive), or empty.
  [[nodiscard]] std::string_view header(std::string_view name) const;
  // Whether the client asked to keep the connection open after this request (RFC 9112 9.3).
  [[nodiscard]] bool wants_keep_alive() const;
  // The peer's IP, or "" when unknown.
  [[nodiscard]] std::string_view remote_ip() const;
};

// A request that owns its bytes, for work that reads it after the connection's buffers have moved
// on (a calculation on the pool): its head in one string, its body in another that the work may
// let go of once it has read it. Neither copied nor moved: its request's views are of itself.
class OwnedRequest {
 public:
  explicit OwnedRequest(const HttpRequest& request);
  OwnedRequest(const OwnedRequest&) = delete;
  OwnedRequest& operator=(const OwnedRequest&) = delete;

  // The request as it was framed, its socket's addresses left out (the connection may be gone).
  [[nodiscard]] const HttpRequest& request() const { return request_; }
  // What request().body views.
  std::string& body_storage() { return body_; }

 private:
  std::string head_;  // method, target, path, then each field's name and value
  std::string body_;
  std::vector<HeaderField> fields_;
  HttpRequest request_;
};

// `path` with its %XX escapes decoded, and the %uXXXX ones (a non-standard form that cpp-httplib,
// which routed cutcalc's requests before its own engine, decodes as UTF-8; kept so that a path
// means what it meant then). A '%' that starts no escape stays; '+' stays '+'.
std::string percent_decode_path(std::string_view path);

// The path of `target` (up to '?'), percent-decoded when it holds a '%' (into `scratch`).
// An absolute-form target ("http://host/path") gives its path; "*" gives "*".
std::string_view request_path(std::string_view target, std::string& scratch);

}  // namespace cutcalc::service
