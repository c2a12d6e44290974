// A body written as it is sent (HttpResponse::body_source), at the byte level: framed chunked for
// HTTP/1.1 and by the close for HTTP/1.0, written only as fast as the client reads, cut short
// (never ended as if whole) when its source throws, and stopped when its client goes.

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

#include "domain/common/text_source.h"
#include "service/http_event_loop.h"
#include "support/gate.h"
#include "support/http_responses.h"

namespace cutcalc::service {
namespace {

constexpr std::size_t kPieceBytes = 64 * 1024;  // what the engine asks for at a time
constexpr int kPatienceMs = 10000;              // a safety net against a hang only

// What a test can see of a source the engine owns.
struct SourceLog {
  std::atomic<std::size_t> calls{0};
  std::atomic<bool> destroyed{false};
};

// `total` bytes of a known pattern; throws on call `throw_at` (0: never).
class PatternSource final : public domain::TextSource {
 public:
  PatternSource(std::size_t total, std::size_t throw_at, std::shared_ptr<SourceLog> log)
      : total_(total), throw_at_(throw_at), log_(std::move(log)) {}
  ~PatternSource() override { log_->destroyed.store(true); }
  PatternSource(const PatternSource&) = delete;
  PatternSource& operator=(const PatternSource&) = delete;

  bool write_next(std::string& out, std::size_t max_bytes) override {
    const std::size_t call = log_->calls.fetch_add(1) + 1;
    if (call == throw_at_) throw std::runtime_error("the generator failed");
    const std::size_t n = std::min(max_bytes, total_ - written_);
    for (std::size_t i = 0; i < n; ++i) out.push_back(byte_at(written_ + i));
    written_ += n;
    return written_ < total_;
  }
  [[nodiscard]] std::size_t held_bytes() const override { return sizeof(*this); }
  static char byte_at(std::size_t i) { return static_cast<char>('a' + i % 26); }

 private:
  std::size_t total_;
  std::size_t throw_at_;
  std::shared_ptr<SourceLog> log_;
  std::size_t written_ = 0;
};

std::string pattern(std::size_t total) {
  std::string text(total, ' ');
  for (std::size_t i = 0; i < total; ++i) text[i] = PatternSource::byte_at(i);
  return text;
}

// "/stream" answers X-Size bytes of the pattern as a body_source (throwing at the X-Throw-At'th
// piece); every other path "light". The source is answered on the loop; its pieces are written on
// the pool.
class StreamingEngine {
 public:
  explicit StreamingEngine(std::chrono::milliseconds write_timeout = std::chrono::seconds(5)) {
    EventLoopSettings settings;
    settings.limits.write_timeout = write_timeout;
    settings.loops = 1;
    settings.pool.threads = 1;
    settings.pool.nice_increment = 0;
    engine_ = std::make_unique<EventLoopEngine>(
        settings, [this](const HttpRequest& request) { return serve(request); },
        [](const EngineError&) {
          return std::string(
              "HTTP/1.1 400 Engine\r\nContent-Length: 0\r\nConnection: close\r\n\r\n");
        },
        [] { return ServerPhase::serving; }, counters_);
  }
  ~StreamingEngine() { engine_.reset(); }
  StreamingEngine(const StreamingEngine&) = delete;
  StreamingEngine& operator=(const StreamingEngine&) = delete;

  EventLoopEngine& engine() { return *engine_; }
  const ConnectionCounters& counters() const { return counters_; }
  const std::shared_ptr<SourceLog>& log() const { return log_; }

 private:
  Reply serve(const HttpRequest& request) {
    HttpResponse response;
    response.content_type = "text/plain";
    if (request.path != "/stream") {
      response.body = "light";
      return response;
    }
    const auto number = [&](std::string_view name) -> std::size_t {
      const std::string_view value = request.header(name);
      return value.empty() ? 0 : std::stoul(std::string(value));
    };
    response.body_source =
        std::make_shared<PatternSource>(number("X-Size"), number("X-Throw-At"), log_);
    return response;
  }

  std::shared_ptr<SourceLog> log_ = std::make_shared<SourceLog>();
  ConnectionCounters counters_;
  std::unique_ptr<EventLoopEngine> engine_;
};

// The client's end of a socketpair the engine adopted.
class Client {
 public:
  explicit Client(EventLoopEngine& engine) {
    int pair[2];
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, pair) != 0) return;
    fd_ = pair[1];
    engine.adopt(pair[0]);
  }
  ~Client() { close(); }
  Client(const Client&) = delete;
  Client& operator=(const Client&) = delete;

  void close() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }
  void send(const std::string& bytes) const {
    ASSERT_EQ(::send(fd_, bytes.data(), bytes.size(), MSG_NOSIGNAL),
              static_cast<ssize_t>(bytes.size()));
  }
  // Reads until `finals` well-framed final responses are in, or the peer closes.
  testing::ParsedResponses read_responses(std::size_t finals) {
    while (true) {
      const testing::ParsedResponses parsed = testing::parse_responses(bytes_);
      if (!parsed.error && parsed.finals() >= finals) return parsed;
      if (!read_some()) return parsed;
    }
  }
  // Reads `bytes` at most, then waits `pause`, until the peer closes.
  void read_slowly(std::size_t bytes, std::chrono::milliseconds pause) {
    std::string buffer(bytes, '\0');
    for (;;) {
      pollfd watched{fd_, POLLIN, 0};
      if (::poll(&watched, 1, kPatienceMs) <= 0) return;
      const ssize_t n = ::recv(fd_, buffer.data(), buffer.size(), MSG_DONTWAIT);
      if (n <= 0) return;
      bytes_.append(buffer.data(), static_cast<std::size_t>(n));
      std::this_thread::sleep_for(pause);
    }
  }
  // Reads until the peer closes; false when the safety net is hit first.
  bool read_to_close() {
    while (read_some()) {
    }
    return closed_;
  }
  [[nodiscard]] const std::string& bytes() const { return bytes_; }

 private:
  bool read_some() {
    pollfd watched{fd_, POLLIN, 0};
    if (::poll(&watched, 1, kPatienceMs) <= 0) return false;
    char buffer[65536];
    const ssize_t n = ::recv(fd_, buffer, sizeof(buffer), MSG_DONTWAIT);
    if (n <= 0) {
      closed_ = n == 0;
      return false;
    }
    bytes_.append(buffer, static_cast<std::size_t>(n));
    return true;
  }

  int fd_ = -1;
  std::string bytes_;
  bool closed_ = false;
};

std::string stream_request(std::size_t size, const std::string& version = "HTTP/1.1",
                           const std::string& extra = {}) {
  return "GET /stream " + version + "\r\nHost: test\r\nX-Size: " + std::to_string(size) + "\r\n" +
         extra + "\r\n";
}

TEST(StreamedBody, ArrivesChunkedAndWholeThenThePipelinedRequestIsServed) {
  StreamingEngine served;
  Client client(served.engine());
  const std::size_t size = 5 * kPieceBytes + 123;  // pieces, and a short last one
  client.send(stream_request(size) + "GET /light HTTP/1.1\r\nHost: test\r\n\r\n");
  const testing::ParsedResponses parsed = client.read_responses(2);
  ASSERT_FALSE(parsed.error) << *parsed.error;
  ASSERT_EQ(parsed.finals(), 2U);
  EXPECT_EQ(parsed.responses[0].header("transfer-encoding"), "chunked");
  EXPECT_EQ(parsed.responses[0].count("content-length"), 0U);
  EXPECT_EQ(parsed.responses[0].body, pattern(size));
  EXPECT_EQ(parsed.responses[1].body, "light");
  EXPECT_TRUE(testing::eventually([&] { return served.log()->destroyed.load(); }));
}

TEST(StreamedBody, AnEmptySourceEndsWithTheLastChunkAlone) {
  StreamingEngine served;
  Client client(served.engine());
  client.send(stream_request(0));
  const testing::ParsedResponses parsed = client.read_responses(1);
  ASSERT_FALSE(parsed.error) << *parsed.error;
  ASSERT_EQ(parsed.finals(), 1U);
  EXPECT_EQ(parsed.responses[0].body, "");
  EXPECT_TRUE(client.bytes().ends_with("\r\n\r\n0\r\n\r\n")) << client.bytes();
}

TEST(StreamedBody, Http10GetsTheBodyUntilTheClose) {
  StreamingEngine served;
  Client client(served.engine());
  const std::size_t size = 3 * kPieceBytes + 7;
  client.send(stream_request(size, "HTTP/1.0", "Connection: keep-alive\r\n"));
  ASSERT_TRUE(client.read_to_close());
  const std::string& bytes = client.bytes();
  const std::size_t head_end = bytes.find("\r\n\r\n");
  ASSERT_NE(head_end, std::string::npos);
  const std::string head = bytes.substr(0, head_end + 2);
  EXPECT_EQ(head.find("Transfer-Encoding"), std::string::npos) << head;
  EXPECT_EQ(head.find("Content-Length"), std::string::npos) << head;
  EXPECT_NE(head.find("Connection: close\r\n"), std::string::npos) << head;
  EXPECT_EQ(bytes.substr(head_end + 4), pattern(size));
}

TEST(StreamedBody, AClientThatDoesNotReadHoldsTheWritingBack) {
  StreamingEngine served;
  Client client(served.engine());
  client.send(stream_request(std::size_t{1} << 30));  // 1 GiB, never read
  ASSERT_TRUE(testing::eventually([&] { return served.log()->calls.load() > 0; }));
  // Once the socket's buffers are full nothing more is asked of the source.
  std::size_t calls = 0;
  for (int settled = 0; settled < 20;) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    const std::size_t now = served.log()->calls.load();
    settled = now == calls ? settled + 1 : 0;
    calls = now;
  }
  EXPECT_LT(calls * kPieceBytes, std::size_t{16} << 20) << calls << " pieces written";
  EXPECT_LT(served.engine().memory_budget().used(), std::uint64_t{1} << 20);
  // The client goes: its source is let go.
  client.close();
  EXPECT_TRUE(testing::eventually([&] { return served.log()->destroyed.load(); }));
}

TEST(StreamedBody, ASlowReaderKeepsItsConnectionPastTheWriteTimeout) {
  StreamingEngine served(std::chrono::milliseconds(100));
  Client client(served.engine());
  const std::size_t size = 2 * 1024 * 1024;  // ~1.3 s at this client's pace, many write timeouts
  client.send(stream_request(size, "HTTP/1.0"));
  client.read_slowly(32 * 1024, std::chrono::milliseconds(20));
  const std::size_t head_end = client.bytes().find("\r\n\r\n");
  ASSERT_NE(head_end, std::string::npos);
  EXPECT_EQ(client.bytes().size() - head_end - 4, size);
}

TEST(StreamedBody, AStalledReaderIsClosedAtTheWriteTimeout) {
  StreamingEngine served(std::chrono::milliseconds(100));
  Client client(served.engine());
  client.send(stream_request(std::size_t{1} << 30));  // never read
  EXPECT_TRUE(testing::eventually([&] { return served.log()->destroyed.load(); }));
}

TEST(StreamedBody, ASourceThatThrowsCutsTheBodyShortAndCloses) {
  StreamingEngine served;
  Client client(served.engine());
  client.send(stream_request(10 * kPieceBytes, "HTTP/1.1", "X-Throw-At: 3\r\n"));
  ASSERT_TRUE(client.read_to_close());
  const testing::ParsedResponses parsed = testing::parse_responses(client.bytes());
  ASSERT_TRUE(parsed.error.has_value()) << "a cut body must not read as whole";
  EXPECT_NE(parsed.error->find("truncated chunked body"), std::string::npos) << *parsed.error;
  EXPECT_EQ(client.bytes().find("\r\n0\r\n\r\n"), std::string::npos);
  EXPECT_EQ(served.counters().streams_broken.load(), 1U);
}

}  // namespace
}  // namespace cutcalc::service
