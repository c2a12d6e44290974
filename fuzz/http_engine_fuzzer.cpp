// Byte-level fuzzer of the HTTP engine: the real service (HttpApp: engine, framing, calculation
// pool, the route table and every handler) serves one end of a socketpair; the fuzzer's bytes go in
// at the other, cut into pieces of fuzzer-chosen sizes, each piece waited on until the engine has
// read it, so that requests arrive split at every place. Then the client half-closes and reads
// until the engine closes.
//
// Input: byte 0 chooses the piece sizes (0: one write), the rest is what the client sends: any
// bytes, usually several requests (the seeds are real requests of every endpoint, chunked bodies,
// Expect: 100-continue, pipelines).
//
// Oracle (abort on a broken promise, so libFuzzer keeps the input):
//  - no sanitizer report (ASan + UBSan; a leak at exit too);
//  - the bytes that come back are well-framed HTTP/1.1 responses (support/http_responses.h);
//  - never more final responses than requests sent: each request the engine answers has its own
//    "HTTP/1." version and its own CRLF CRLF, and one rejection may end the connection;
//  - no 500; every 4xx/5xx is application/problem+json with a cutcalc problem type, its status,
//    and an X-Request-Id;
//  - the engine closes the connection after the client's half-close;
//  - a fresh connection is still answered (GET /healthz: 200).

#include <poll.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <linux/sockios.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <string_view>
#include <thread>

#include <nlohmann/json.hpp>

#include "service/config.h"
#include "service/http_app.h"
#include "support/http_responses.h"

namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

// A whole exchange must end within this; the engine closes at once after a half-close, so only a
// hang (a bug) reaches it. libFuzzer's -timeout is the outer bound.
constexpr milliseconds kExchangeLimit{20000};
// How long one piece may wait to be read before the next is sent anyway (the engine stops reading
// while a response waits for the client, or after its last response).
constexpr milliseconds kPieceWait{5};

cutcalc::service::HttpApp* g_app = nullptr;

[[noreturn]] void broken(const std::string& what, std::string_view received) {
  std::fprintf(stderr, "http_engine_fuzzer: %s\n--- received (%zu bytes, first 2000):\n%.*s\n",
               what.c_str(), received.size(),
               static_cast<int>(std::min<std::size_t>(received.size(), 2000)), received.data());
  std::abort();
}

void start_service() {
  cutcalc::service::Config config;
  config.host = "127.0.0.1";
  config.port = 0;
  config.log_level = "off";
  config.http.event_loop_threads = 1;
  static cutcalc::service::HttpApp app(config);  // lives for the process (no leak report)
  if (app.bind() <= 0) {
    std::fprintf(stderr, "http_engine_fuzzer: cannot bind a loopback port\n");
    std::abort();
  }
  static std::thread serving([] { app.serve(); });
  serving.detach();
  g_app = &app;
}

// Reads whatever is there now (non-blocking); false once the peer has closed.
bool read_available(int fd, std::string& into) {
  char buffer[65536];
  for (;;) {
    const ssize_t n = ::recv(fd, buffer, sizeof buffer, MSG_DONTWAIT);
    if (n > 0) {
      into.append(buffer, static_cast<std::size_t>(n));
      continue;
    }
    if (n == 0) return false;
    return errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR;
  }
}

// Bytes written to `fd` that its peer has not read yet (AF_UNIX: SIOCOUTQ).
int unread_by_peer(int fd) {
  int queued = 0;
  return ::ioctl(fd, SIOCOUTQ, &queued) == 0 ? queued : 0;
}

std::size_t piece_size(std::uint8_t chooser, std::size_t index) {
  if (chooser == 0) return SIZE_MAX;
  // A repeating pattern of sizes 1..4*chooser, so both byte-by-byte and larger pieces occur.
  const std::uint64_t mixed = (static_cast<std::uint64_t>(index) + 1) * 2654435761U * chooser;
  return 1 + static_cast<std::size_t>(mixed % (4U * chooser));
}

// Sends `bytes` in pieces over a new connection, half-closes, reads until the engine closes.
std::string converse(std::string_view bytes, std::uint8_t chooser) {
  int pair[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, pair) != 0) broken("socketpair", {});
  const int client = pair[0];
  g_app->serve_connection(pair[1]);
  const auto until = Clock::now() + kExchangeLimit;
  std::string received;
  bool open = true;
  for (std::size_t index = 0; !bytes.empty() && open; ++index) {
    const std::size_t size = std::min(piece_size(chooser, index), bytes.size());
    const ssize_t n = ::send(client, bytes.data(), size, MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n > 0) bytes.remove_prefix(static_cast<std::size_t>(n));
    if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK) break;  // the engine closed
    const auto piece_until = Clock::now() + kPieceWait;
    while (unread_by_peer(client) > 0 && Clock::now() < piece_until) {
      open = read_available(client, received);
      if (!open) break;
      std::this_thread::yield();
    }
    open = open && read_available(client, received);
    if (Clock::now() > until) broken("the exchange did not end in time (sending)", received);
  }
  ::shutdown(client, SHUT_WR);
  while (open) {
    pollfd readable{client, POLLIN, 0};
    ::poll(&readable, 1, 100);
    open = read_available(client, received);
    if (open && Clock::now() > until) {
      broken("the engine did not close the connection after the client's half-close", received);
    }
  }
  ::close(client);
  return received;
}

std::size_t occurrences(std::string_view text, std::string_view what) {
  std::size_t count = 0;
  for (std::size_t at = text.find(what); at != std::string_view::npos;
       at = text.find(what, at + 1)) {
    ++count;
  }
  return count;
}

void check(std::string_view sent, std::string_view received) {
  // converse() read until the engine closed.
  const auto parsed =
      cutcalc::testing::parse_responses(received, cutcalc::testing::ConnectionState::closed);
  if (parsed.error) broken("not well-framed HTTP/1.1: " + *parsed.error, received);
  const std::size_t requests =
      std::min(occurrences(sent, "HTTP/1."), occurrences(sent, "\r\n\r\n")) + 1;
  if (parsed.finals() > requests) {
    broken(std::to_string(parsed.finals()) + " responses to at most " + std::to_string(requests) +
               " requests",
           received);
  }
  for (const auto& response : parsed.responses) {
    if (response.interim()) continue;
    if (response.status == 500) broken("a 500", received);
    if (response.count("x-request-id") != 1) broken("no X-Request-Id", received);
    if (response.status < 400) continue;
    if (response.header("content-type") != "application/problem+json") {
      broken("an error that is not problem+json", received);
    }
    if (response.body.empty()) continue;  // a HEAD request's
    const auto problem = nlohmann::json::parse(response.body, nullptr, false);
    if (!problem.is_object() || !problem.contains("type") || !problem["type"].is_string() ||
        problem["type"].get<std::string>().rfind("urn:cutcalc:problem:", 0) != 0 ||
        problem.value("status", 0) != response.status || !problem.contains("instance")) {
      broken("a malformed problem body", received);
    }
  }
}

void check_fresh_connection() {
  constexpr std::string_view kProbe =
      "GET /healthz HTTP/1.1\r\nHost: fuzz\r\nConnection: close\r\n\r\n";
  const std::string received = converse(kProbe, 0);
  const auto parsed =
      cutcalc::testing::parse_responses(received, cutcalc::testing::ConnectionState::closed);
  if (parsed.error || parsed.finals() != 1 || parsed.responses.back().status != 200) {
    broken("a fresh connection was not answered 200", received);
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  start_service();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view sent(reinterpret_cast<const char*>(data) + 1, size - 1);
  check(sent, converse(sent, data[0]));
  check_fresh_connection();
  return 0;
}
