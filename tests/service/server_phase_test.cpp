// The server's phase is read once per request (HttpRequest::phase): the engine's keep-alive
// decision and the app's answer use the same snapshot. The phase here changes on every read, which
// forces the interleaving a SIGTERM can only sometimes produce (/readyz answering 503 while the
// engine, having read the phase a moment earlier, kept the connection open).

#include <gtest/gtest.h>

#include <atomic>
#include <memory>
#include <string>

#include "service/http_event_loop.h"
#include "support/engine_client.h"

namespace cutcalc::service {
namespace {

using testing::EngineClient;
using testing::ParsedResponses;

// Answers each request with the phase it carries: "serving", or "not serving" as a 503.
class PhaseEchoEngine {
 public:
  PhaseEchoEngine() {
    EventLoopSettings settings = testing::small_engine_settings();
    engine_ = std::make_unique<EventLoopEngine>(
        settings,
        [](const HttpRequest& request) -> Reply {
          HttpResponse response;
          const bool serving = request.phase == ServerPhase::serving;
          response.status = serving ? 200 : 503;
          response.set_content(serving ? "serving" : "not serving", "text/plain");
          return response;
        },
        testing::bare_engine_error,
        // Every read of the phase flips it.
        [this] {
          return reads_.fetch_add(1) % 2 == 0 ? ServerPhase::serving : ServerPhase::draining;
        },
        counters_);
  }
  ~PhaseEchoEngine() { engine_.reset(); }
  PhaseEchoEngine(const PhaseEchoEngine&) = delete;
  PhaseEchoEngine& operator=(const PhaseEchoEngine&) = delete;

  EventLoopEngine& engine() { return *engine_; }

 private:
  std::atomic<unsigned> reads_{0};
  ConnectionCounters counters_;
  std::unique_ptr<EventLoopEngine> engine_;
};

TEST(ServerPhase, AnAnswerThatSaysNotServingAlwaysClosesItsConnection) {
  PhaseEchoEngine server;
  int serving = 0;
  int not_serving = 0;
  for (int i = 0; i < 40; ++i) {
    EngineClient client(server.engine());
    client.send("GET /readyz HTTP/1.1\r\nHost: cutcalc\r\n\r\n");
    const ParsedResponses parsed = client.read_responses(1);
    ASSERT_FALSE(parsed.error) << *parsed.error << "\n" << client.bytes();
    ASSERT_EQ(parsed.finals(), 1U) << client.bytes();
    const auto& response = parsed.responses.back();
    if (response.status == 200) {
      ++serving;
      EXPECT_NE(response.header("connection"), "close") << client.bytes();
    } else {
      ++not_serving;
      EXPECT_EQ(response.status, 503) << client.bytes();
      EXPECT_EQ(response.header("connection"), "close") << client.bytes();
    }
  }
  // The phase changed between requests, so both kinds of answer were checked.
  EXPECT_GT(serving, 0);
  EXPECT_GT(not_serving, 0);
}

}  // namespace
}  // namespace cutcalc::service
