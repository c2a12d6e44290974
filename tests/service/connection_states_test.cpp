// A connection's states (what it waits for: the next request, the rest of one, the pool's answer,
// the pool's next piece of a body, the socket, the client's end after the last response), each
// driven at the byte level into its transition: the event that ends it, and its own deadline.
// The timeouts are short so that a deadline passes while the test waits; no test measures time.

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <string>
#include <thread>

#include "domain/common/text_source.h"
#include "service/http_event_loop.h"
#include "support/engine_client.h"
#include "support/gate.h"

namespace cutcalc::service {
namespace {

using std::chrono::milliseconds;
using testing::EngineClient;
using testing::parse_responses;
using testing::ParsedResponses;

// Until the engine has closed every connection (false after the clients' patience).
bool until_all_closed(const EventLoopEngine& engine) {
  const auto until = std::chrono::steady_clock::now() + EngineClient::kPatience;
  while (engine.open_connections() > 0) {
    if (std::chrono::steady_clock::now() >= until) return false;
    std::this_thread::sleep_for(milliseconds(20));
  }
  return true;
}

constexpr milliseconds kShort{300};
constexpr std::size_t kLargeBody = 8 * 1024 * 1024;  // more than socket buffers hold

// A body whose second piece waits for `release` (a piece stuck on the pool).
class StuckSource final : public domain::TextSource {
 public:
  explicit StuckSource(std::shared_ptr<testing::Gate> release) : release_(std::move(release)) {}
  bool write_next(std::string& out, std::size_t) override {
    if (++calls_ > 1) release_->pass();
    out += "piece";
    return calls_ < 3;
  }
  [[nodiscard]] std::size_t held_bytes() const override { return sizeof(*this); }

 private:
  std::shared_ptr<testing::Gate> release_;
  int calls_ = 0;
};

// "/light": 200 at once. "/large": kLargeBody bytes at once. "/calculate": on the pool until its
// calculation is stopped (a timeout, a client gone), settled 503 when timed out. "/stuck": a
// streamed body whose second piece waits for the gate.
class StatesEngine {
 public:
  StatesEngine() {
    EventLoopSettings settings = testing::small_engine_settings(2);
    settings.limits.keep_alive_timeout = std::chrono::seconds(1);
    settings.limits.request_timeout = kShort;
    settings.limits.write_timeout = kShort;
    settings.limits.calculation_timeout = kShort;
    settings.limits.linger_time = kShort;
    engine_ = std::make_unique<EventLoopEngine>(
        settings, [this](const HttpRequest& request) { return serve(request); },
        testing::bare_engine_error, [] { return ServerPhase::serving; }, counters_);
  }
  ~StatesEngine() {
    release_->open();  // a stuck piece ends before the pool goes
    engine_.reset();
  }
  StatesEngine(const StatesEngine&) = delete;
  StatesEngine& operator=(const StatesEngine&) = delete;

  EventLoopEngine& engine() { return *engine_; }
  const ConnectionCounters& counters() const { return counters_; }
  std::size_t abandoned() const { return abandoned_.load(); }

 private:
  Reply serve(const HttpRequest& request) {
    HttpResponse response;
    if (request.path == "/large") {
      response.set_content(std::string(kLargeBody, 'x'), "text/plain");
      return response;
    }
    if (request.path == "/stuck") {
      response.content_type = "text/plain";
      response.body_source = std::make_shared<StuckSource>(release_);
      return response;
    }
    if (request.path != "/calculate") {
      response.set_content("light", "text/plain");
      return response;
    }
    DeferredResponse work;
    work.run = [](OwnedRequest&, const std::atomic<bool>& stop) {
      while (!stop.load()) std::this_thread::sleep_for(milliseconds(5));
      return HttpResponse{};
    };
    work.settle = [this](DeferredOutcome outcome, HttpResponse computed, std::string_view) {
      if (outcome == DeferredOutcome::abandoned) abandoned_.fetch_add(1);
      if (outcome != DeferredOutcome::timed_out) return computed;
      HttpResponse busy;
      busy.status = 503;
      busy.set_content("late", "text/plain");
      return busy;
    };
    return work;
  }

  ConnectionCounters counters_;
  std::atomic<std::size_t> abandoned_{0};
  std::shared_ptr<testing::Gate> release_ = std::make_shared<testing::Gate>();
  std::unique_ptr<EventLoopEngine> engine_;
};

std::string get(const std::string& path, const std::string& extra = {}) {
  return "GET " + path + " HTTP/1.1\r\nHost: cutcalc\r\n" + extra + "\r\n";
}

TEST(ConnectionStates, IdleTakesTheNextRequestAndClosesAtTheKeepAliveTimeout) {
  StatesEngine server;
  EngineClient client(server.engine());
  client.send(get("/light"));
  client.send(get("/light"));
  const ParsedResponses parsed = client.read_responses(2);
  ASSERT_EQ(parsed.finals(), 2U) << client.bytes();
  EXPECT_NE(parsed.responses.back().header("connection"), "close");
  EXPECT_TRUE(client.read_to_close()) << "an idle connection outlived its keep-alive timeout";
  EXPECT_EQ(parse_responses(client.bytes()).finals(), 2U) << client.bytes();
}

TEST(ConnectionStates, ARequestInPiecesIsAnsweredWhenWholeAndTheConnectionStays) {
  StatesEngine server;
  EngineClient client(server.engine());
  const std::string request = get("/light");
  client.send(request.substr(0, 10));
  client.send(request.substr(10));
  ASSERT_EQ(client.read_responses(1).finals(), 1U) << client.bytes();
  client.send(get("/light"));
  EXPECT_EQ(client.read_responses(2).finals(), 2U) << client.bytes();
}

TEST(ConnectionStates, APartialRequestClosesAtTheRequestTimeoutUnanswered) {
  StatesEngine server;
  EngineClient client(server.engine());
  client.send("GET /light HTTP/1.1\r\nHost: cut");
  EXPECT_TRUE(client.read_to_close());
  EXPECT_EQ(client.bytes(), "");
  EXPECT_EQ(server.counters().request_timeouts.load(), 1U);
}

TEST(ConnectionStates, ACalculationPastItsTimeoutIsAnswered503AndClosed) {
  StatesEngine server;
  EngineClient client(server.engine());
  client.send(get("/calculate"));
  const ParsedResponses parsed = client.read_responses(1);
  ASSERT_EQ(parsed.finals(), 1U) << client.bytes();
  EXPECT_EQ(parsed.responses.back().status, 503);
  EXPECT_EQ(parsed.responses.back().header("connection"), "close");
  EXPECT_TRUE(client.read_to_close());
  EXPECT_EQ(server.counters().calculation_timeouts.load(), 1U);
}

TEST(ConnectionStates, ACalculationWhoseClientEndsItsInputIsAbandoned) {
  StatesEngine server;
  EngineClient client(server.engine());
  client.send(get("/calculate"));
  client.shut_down_writing();
  EXPECT_TRUE(client.read_to_close());
  EXPECT_EQ(client.bytes(), "");
  EXPECT_EQ(server.abandoned(), 1U);
  EXPECT_EQ(server.counters().calculation_timeouts.load(), 0U);
}

TEST(ConnectionStates, OutputTheClientNeverReadsClosesAtTheWriteTimeout) {
  StatesEngine server;
  EngineClient client(server.engine());
  client.send(get("/large"));
  // Not reading until the engine has given up on the output.
  ASSERT_TRUE(until_all_closed(server.engine()));
  client.read_to_close();
  EXPECT_LT(client.bytes().size(), kLargeBody) << "the whole body went to a client that never read";
}

TEST(ConnectionStates, APieceStuckOnThePoolCutsTheBodyShortAtItsDeadline) {
  StatesEngine server;
  EngineClient client(server.engine());
  client.send(get("/stuck"));
  EXPECT_TRUE(client.read_to_close());
  const ParsedResponses parsed = parse_responses(client.bytes(), testing::ConnectionState::closed);
  EXPECT_TRUE(parsed.error) << "a body cut short was framed as whole:\n" << client.bytes();
  EXPECT_NE(client.bytes().find("piece"), std::string::npos) << client.bytes();
}

TEST(ConnectionStates, AfterTheLastResponseInputIsDroppedUntilTheLingerTimeCloses) {
  StatesEngine server;
  EngineClient client(server.engine());
  client.send(get("/light", "Connection: close\r\n"));
  client.send(get("/light"));  // after the last request: never answered
  EXPECT_TRUE(client.read_to_close()) << "no end of output after the last response";
  EXPECT_EQ(parse_responses(client.bytes()).finals(), 1U) << client.bytes();
  // The engine still reads (and drops) what comes, until the linger time closes it.
  client.send("more bytes after the end");
  EXPECT_TRUE(until_all_closed(server.engine()));
}

}  // namespace
}  // namespace cutcalc::service
