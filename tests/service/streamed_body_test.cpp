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
#include "support/engine_client.h"
#include "support/gate.h"
#include "support/http_responses.h"

namespace cutcalc::service {
namespace {

constexpr std::size_t kPieceBytes = 64 * 1024;  // what the engine asks for at a time

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
    EventLoopSettings settings = testing::small_engine_settings();
    settings.limits.write_timeout = write_timeout;
    engine_ = std::make_unique<EventLoopEngine>(
        settings, [this](const HttpRequest& request) { return serve(request); },
        testing::bare_engine_error, [] { return ServerPhase::serving; }, counters_);
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

using Client = testing::EngineClient;

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
  // Well-framed once the connection has closed (RFC 9112 6.3 rule 8), not before.
  const auto parsed = testing::parse_responses(bytes, testing::ConnectionState::closed);
  ASSERT_FALSE(parsed.error) << *parsed.error;
  ASSERT_EQ(parsed.finals(), 1U);
  EXPECT_EQ(parsed.responses[0].body, pattern(size));
  EXPECT_TRUE(testing::parse_responses(bytes).error.has_value());
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

// A client that half-closed after its request (`nc -N`) still reads: a body that has begun is
// finished, then the connection closes.
TEST(StreamedBody, AHalfCloseDoesNotCutABodyThatHasBegun) {
  StreamingEngine served;
  Client client(served.engine());
  const std::size_t size = 64 * kPieceBytes;  // far more than the socket's buffers
  client.send(stream_request(size));
  ASSERT_TRUE(testing::eventually([&] { return served.log()->calls.load() > 0; }));
  client.shut_down_writing();
  ASSERT_TRUE(client.read_to_close());
  const testing::ParsedResponses parsed = testing::parse_responses(client.bytes());
  ASSERT_FALSE(parsed.error) << *parsed.error;
  ASSERT_EQ(parsed.finals(), 1U);
  EXPECT_EQ(parsed.responses[0].body, pattern(size));
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
