// Heavy work never holds up light work, shown without timing: the engine's calculation hook (a
// DeferredResponse) is held on a test gate while other requests are answered, a full pool is
// answered at once with its refusal, and pipelined requests keep their order. The engine takes any
// stream socket, so each connection here is a socketpair; the last test goes through the real
// service and its metrics.

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <regex>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "service/http_event_loop.h"
#include "support/engine_client.h"
#include "support/gate.h"
#include "support/http_responses.h"
#include "support/test_server.h"

namespace cutcalc::service {
namespace {

// An answer far larger than the socket's buffers, and a memory budget it spends alone.
constexpr std::size_t kBigAnswerBytes = 4 * 1024 * 1024;
constexpr std::uint64_t kSmallBudgetBytes = 1024 * 1024;  // less than a large body

using cutcalc::testing::eventually;
using cutcalc::testing::Gate;

HttpResponse text(int status, std::string body) {
  HttpResponse response;
  response.status = status;
  response.set_content(std::move(body), "text/plain");
  return response;
}

using Client = testing::EngineClient;

std::string request(const std::string& method, const std::string& path,
                    const std::string& extra = {}) {
  return method + " " + path + " HTTP/1.1\r\nHost: test\r\n" + extra + "\r\n";
}

// An engine whose "/heavy" goes to the pool and waits at the gate there (answering "heavy
// <X-Tag>", or X-Size bytes of it), "/stuck" spins on the pool until it is stopped, "/throw" throws
// there (a std::exception, or an int with "X-Tag: int"); refused with 503 + Retry-After when the
// pool is full; every other path is answered "light" on the loop. The pool has one thread and room
// for one waiting job. Every settled request's outcome is recorded.
class HeldEngine {
 public:
  explicit HeldEngine(std::size_t loops,
                      std::chrono::milliseconds calculation_timeout = std::chrono::seconds(60),
                      std::uint64_t memory_budget_bytes = UINT64_MAX) {
    EventLoopSettings settings;
    settings.loops = loops;
    settings.pool.threads = 1;
    settings.pool.queue_limit = 1;
    settings.pool.nice_increment = 0;
    settings.limits.calculation_timeout = calculation_timeout;
    settings.limits.large_body_routes = {{"/heavy", 8 * 1024 * 1024}};
    settings.memory_budget_bytes = memory_budget_bytes;
    engine_ = std::make_unique<EventLoopEngine>(
        settings, [this](const HttpRequest& request) { return serve(request); },
        [](const EngineError& error) {
          return "HTTP/1.1 " + std::to_string(http_status(error.fault)) +
                 " Engine\r\nContent-Length: 0\r\nX-Busy: " +
                 (error.fault == HttpFault::memory_busy    ? "memory"
                  : error.fault == HttpFault::uploads_busy ? "uploads"
                                                           : "none") +
                 "\r\nConnection: close\r\n\r\n";
        },
        [] { return ServerPhase::serving; }, counters_);
  }
  ~HeldEngine() {
    gate_.open();  // the pool finishes its jobs before the engine is gone
    engine_.reset();
  }
  HeldEngine(const HeldEngine&) = delete;
  HeldEngine& operator=(const HeldEngine&) = delete;

  EventLoopEngine& engine() { return *engine_; }
  Gate& gate() { return gate_; }
  const WorkPoolCounters& pool() const { return counters_.calculations; }
  const ConnectionCounters& counters() const { return counters_; }
  // "/stuck" jobs that saw their stop flag.
  [[nodiscard]] int stopped() const { return stopped_.load(); }
  [[nodiscard]] std::vector<DeferredOutcome> settled() {
    const std::lock_guard lock(mutex_);
    return settled_;
  }

 private:
  Reply serve(const HttpRequest& request) {
    if (request.path != "/heavy" && request.path != "/stuck" && request.path != "/throw") {
      return text(200, "light");
    }
    return DeferredResponse{
        [this, path = std::string(request.path), tag = std::string(request.header("X-Tag"))](
            OwnedRequest&, const std::atomic<bool>& stop) {
          if (path == "/stuck") {
            while (!stop.load()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
            stopped_.fetch_add(1);
            throw std::runtime_error("stopped");  // what domain::Interrupted does
          }
          if (path == "/throw") {
            if (tag == "int") throw 42;
            throw std::runtime_error("broken " + tag);
          }
          gate_.pass();
          return text(200, tag == "big" ? std::string(kBigAnswerBytes, 'x') : "heavy " + tag);
        },
        [this](DeferredOutcome outcome, HttpResponse computed, std::string_view failure) {
          {
            const std::lock_guard lock(mutex_);
            settled_.push_back(outcome);
          }
          switch (outcome) {
            case DeferredOutcome::computed:
              return computed;
            case DeferredOutcome::failed:
              return text(500, "failed: " + std::string(failure));
            case DeferredOutcome::pool_full:
            case DeferredOutcome::over_budget:
            case DeferredOutcome::timed_out: {
              HttpResponse busy =
                  text(503, outcome == DeferredOutcome::pool_full     ? "busy"
                            : outcome == DeferredOutcome::over_budget ? "over budget"
                                                                      : "timed out");
              busy.set_header("Retry-After", "1");
              return busy;
            }
            case DeferredOutcome::abandoned:
              break;
          }
          return text(499, "");
        }};
  }

  Gate gate_;
  std::atomic<int> stopped_{0};
  std::mutex mutex_;
  std::vector<DeferredOutcome> settled_;  // guarded by mutex_
  ConnectionCounters counters_;
  std::unique_ptr<EventLoopEngine> engine_;
};

TEST(CalculationPool, LightRequestIsAnsweredWhileAHeavyOneIsHeld) {
  HeldEngine held(1);  // one loop: the light request shares the heavy one's loop
  Client heavy(held.engine());
  Client light(held.engine());
  heavy.send(request("GET", "/heavy", "X-Tag: a\r\n"));
  ASSERT_TRUE(held.gate().wait_inside(1));

  light.send(request("GET", "/light"));
  const testing::ParsedResponses answered = light.read_responses(1);
  ASSERT_EQ(answered.finals(), 1U) << light.bytes();
  EXPECT_EQ(answered.responses[0].status, 200);
  EXPECT_EQ(answered.responses[0].body, "light");
  EXPECT_EQ(heavy.arrived_now(), "") << "the heavy answer came before its gate opened";

  held.gate().open();
  const testing::ParsedResponses late = heavy.read_responses(1);
  ASSERT_EQ(late.finals(), 1U) << heavy.bytes();
  EXPECT_EQ(late.responses[0].body, "heavy a");
}

TEST(CalculationPool, FullPoolIsRefusedAtOnceWithRetryAfter) {
  HeldEngine held(2);
  Client first(held.engine());
  Client second(held.engine());
  Client third(held.engine());
  first.send(request("GET", "/heavy", "X-Tag: 1\r\n"));
  ASSERT_TRUE(held.gate().wait_inside(1));  // the pool's one thread is held
  second.send(request("GET", "/heavy", "X-Tag: 2\r\n"));
  ASSERT_TRUE(eventually([&] { return held.pool().queued.load() == 1; }));  // the queue is full

  third.send(request("GET", "/heavy", "X-Tag: 3\r\n"));
  const testing::ParsedResponses refused = third.read_responses(1);
  ASSERT_EQ(refused.finals(), 1U) << third.bytes();
  EXPECT_EQ(refused.responses[0].status, 503);
  EXPECT_EQ(refused.responses[0].header("retry-after"), "1");
  EXPECT_EQ(held.pool().refused.load(), 1U);

  held.gate().open();
  const testing::ParsedResponses one = first.read_responses(1);
  const testing::ParsedResponses two = second.read_responses(1);
  ASSERT_EQ(one.finals(), 1U) << first.bytes();
  ASSERT_EQ(two.finals(), 1U) << second.bytes();
  EXPECT_EQ(one.responses[0].body, "heavy 1");
  EXPECT_EQ(two.responses[0].body, "heavy 2");
  EXPECT_EQ(held.pool().jobs.load(), 2U);
}

TEST(CalculationPool, PipelinedRequestsAreAnsweredInOrderBehindAHeldOne) {
  HeldEngine held(1);
  Client client(held.engine());
  client.send(request("GET", "/heavy", "X-Tag: first\r\n") + request("GET", "/light"));
  ASSERT_TRUE(held.gate().wait_inside(1));
  held.gate().open();
  const testing::ParsedResponses answered = client.read_responses(2);
  ASSERT_EQ(answered.finals(), 2U) << client.bytes();
  EXPECT_EQ(answered.responses[0].body, "heavy first");
  EXPECT_EQ(answered.responses[1].body, "light");
}

TEST(CalculationPool, AnswerForAConnectionClosedMeanwhileGoesNowhere) {
  HeldEngine held(1);
  auto gone = std::make_unique<Client>(held.engine());
  const int gone_fd = gone->server_fd();
  gone->send(request("GET", "/heavy", "X-Tag: stale\r\n"));
  ASSERT_TRUE(held.gate().wait_inside(1));
  gone.reset();  // the client hangs up while its calculation runs
  ASSERT_TRUE(eventually([&] { return held.engine().open_connections() == 0; }));

  // Most likely on the descriptor number the closed connection had: the stale answer must still
  // not reach it (the engine tells connections apart by id, not descriptor).
  Client next(held.engine());
  SCOPED_TRACE(next.server_fd() == gone_fd ? "descriptor reused" : "descriptor not reused");
  held.gate().open();
  ASSERT_TRUE(eventually([&] {
    return held.pool().jobs.load() == 1 && held.pool().running.load() == 0;
  }));  // the stale answer is posted to the loop
  next.send(request("GET", "/light", "Connection: close\r\n"));
  ASSERT_TRUE(next.read_to_close()) << next.bytes();
  const testing::ParsedResponses answered = testing::parse_responses(next.bytes());
  ASSERT_FALSE(answered.error) << *answered.error;
  ASSERT_EQ(answered.finals(), 1U) << next.bytes();
  EXPECT_EQ(answered.responses[0].body, "light");
}

TEST(CalculationPool, CalculationPastItsTimeoutIsAnswered503AndStopped) {
  HeldEngine held(1, std::chrono::milliseconds(50));
  Client client(held.engine());
  client.send(request("GET", "/stuck"));
  ASSERT_TRUE(client.read_to_close()) << client.bytes();
  const testing::ParsedResponses answered = testing::parse_responses(client.bytes());
  ASSERT_FALSE(answered.error) << *answered.error;
  ASSERT_EQ(answered.finals(), 1U) << client.bytes();
  EXPECT_EQ(answered.responses[0].status, 503);
  EXPECT_EQ(answered.responses[0].header("retry-after"), "1");
  EXPECT_EQ(answered.responses[0].header("connection"), "close");
  ASSERT_TRUE(eventually([&] { return held.stopped() == 1; }));
  EXPECT_EQ(held.counters().calculation_timeouts.load(), 1U);
  EXPECT_EQ(held.settled(), std::vector{DeferredOutcome::timed_out});
}

TEST(CalculationPool, CalculationThatThrowsIsAnswered500AndTheConnectionGoesOn) {
  HeldEngine held(1);
  Client client(held.engine());
  client.send(request("GET", "/throw", "X-Tag: std\r\n") +
              request("GET", "/throw", "X-Tag: int\r\n") +
              request("GET", "/light", "Connection: close\r\n"));
  ASSERT_TRUE(client.read_to_close()) << client.bytes();
  const testing::ParsedResponses answered = testing::parse_responses(client.bytes());
  ASSERT_FALSE(answered.error) << *answered.error;
  ASSERT_EQ(answered.finals(), 3U) << client.bytes();
  EXPECT_EQ(answered.responses[0].status, 500);
  EXPECT_EQ(answered.responses[0].body, "failed: broken std");
  EXPECT_EQ(answered.responses[1].status, 500);
  EXPECT_EQ(answered.responses[1].body, "failed: an exception that is not a std::exception");
  EXPECT_EQ(answered.responses[2].body, "light");
}

TEST(CalculationPool, ClientThatHangsUpStopsItsCalculation) {
  HeldEngine held(1);
  auto gone = std::make_unique<Client>(held.engine());
  gone->send(request("GET", "/stuck"));
  ASSERT_TRUE(eventually([&] { return held.pool().running.load() == 1; }));
  gone.reset();
  ASSERT_TRUE(eventually([&] { return held.stopped() == 1; }));
  EXPECT_EQ(held.counters().calculations_abandoned.load(), 1U);
  EXPECT_EQ(held.settled(), std::vector{DeferredOutcome::abandoned});
}

// As nginx does (proxy_ignore_client_abort off): the end of the client's input while its
// calculation runs means it has gone; TCP cannot tell a half-close from a close before a write.
TEST(CalculationPool, ClientThatEndsItsInputStopsItsCalculation) {
  HeldEngine held(1);
  Client client(held.engine());
  client.send(request("GET", "/stuck"));
  ASSERT_TRUE(eventually([&] { return held.pool().running.load() == 1; }));
  client.shut_down_writing();
  ASSERT_TRUE(eventually([&] { return held.stopped() == 1; }));
  EXPECT_TRUE(client.read_to_close());
  EXPECT_EQ(held.settled(), std::vector{DeferredOutcome::abandoned});
}

TEST(CalculationPool, SpentBudgetRefusesACalculationBeforeItRuns) {
  HeldEngine held(1, std::chrono::seconds(60), kSmallBudgetBytes);
  held.gate().open();
  Client uploading(held.engine());  // a large body, counted whole (as held) from its head
  uploading.send("POST /heavy HTTP/1.1\r\nHost: test\r\nContent-Length: " +
                 std::to_string(kSmallBudgetBytes / kLargeBodyHeldTimes) + "\r\n\r\n" +
                 std::string(1000, 'b'));
  ASSERT_TRUE(eventually([&] { return held.engine().memory_budget().spent(); }));

  Client refused(held.engine());
  refused.send(request("GET", "/heavy", "X-Tag: later\r\n"));
  const testing::ParsedResponses over = refused.read_responses(1);
  ASSERT_EQ(over.finals(), 1U) << refused.bytes();
  EXPECT_EQ(over.responses[0].status, 503);
  EXPECT_EQ(over.responses[0].body, "over budget");
  EXPECT_EQ(over.responses[0].header("retry-after"), "1");
  EXPECT_EQ(held.pool().jobs.load(), 0U) << "refused before it ran";
  EXPECT_EQ(held.counters().memory_refused.load(), 1U);

  uploading.close();
  ASSERT_TRUE(eventually([&] { return held.engine().memory_budget().used() == 0; }));
  refused.send(request("GET", "/heavy", "X-Tag: now\r\n"));
  const testing::ParsedResponses served = refused.read_responses(2);
  ASSERT_EQ(served.finals(), 2U) << refused.bytes();
  EXPECT_EQ(served.responses[1].body, "heavy now");
}

TEST(CalculationPool, AnswerWaitingForItsClientIsCountedUntilItIsRead) {
  HeldEngine held(1);
  held.gate().open();
  Client slow(held.engine());
  slow.send(request("GET", "/heavy", "X-Tag: big\r\n"));  // and reads nothing yet
  ASSERT_TRUE(eventually([&] { return held.engine().memory_budget().used() > 0; }));
  EXPECT_LE(held.engine().memory_budget().used(), kBigAnswerBytes + 1024);
  const testing::ParsedResponses big = slow.read_responses(1);
  ASSERT_EQ(big.finals(), 1U);
  EXPECT_EQ(big.responses[0].body.size(), kBigAnswerBytes);
  ASSERT_TRUE(eventually([&] { return held.engine().memory_budget().used() == 0; }));
}

TEST(CalculationPool, AnswerTheBudgetCannotHoldIsDroppedAndAnswered503) {
  HeldEngine held(1, std::chrono::seconds(60), kBigAnswerBytes * 3 / 2);
  held.gate().open();
  Client slow(held.engine());
  slow.send(request("GET", "/heavy", "X-Tag: big\r\n"));
  ASSERT_TRUE(eventually([&] { return held.engine().memory_budget().used() > 0; }));

  Client second(held.engine());
  second.send(request("GET", "/heavy", "X-Tag: big\r\n"));
  const testing::ParsedResponses over = second.read_responses(1);
  ASSERT_EQ(over.finals(), 1U) << second.bytes().substr(0, 200);
  EXPECT_EQ(over.responses[0].status, 503);
  EXPECT_EQ(over.responses[0].body, "over budget");
  EXPECT_EQ(held.pool().jobs.load(), 2U) << "it ran, and its answer did not fit";
  EXPECT_LE(held.engine().memory_budget().used(), kBigAnswerBytes);
  slow.close();
  ASSERT_TRUE(eventually([&] { return held.engine().memory_budget().used() == 0; }));
}

TEST(CalculationPool, LargeBodyTheBudgetCannotTakeIsRefusedBeforeItIsRead) {
  HeldEngine held(1, std::chrono::seconds(60), kSmallBudgetBytes);
  Client client(held.engine());
  client.send("POST /heavy HTTP/1.1\r\nHost: test\r\nContent-Length: 2097152\r\n\r\n");
  ASSERT_TRUE(client.read_to_close()) << client.bytes();
  const testing::ParsedResponses answered = testing::parse_responses(client.bytes());
  ASSERT_EQ(answered.finals(), 1U) << client.bytes();
  EXPECT_EQ(answered.responses[0].status, 503);
  EXPECT_EQ(answered.responses[0].header("x-busy"), "memory");
  EXPECT_EQ(held.counters().memory_refused.load(), 1U);
  EXPECT_EQ(held.engine().memory_budget().used(), 0U);
}

TEST(CalculationPool, LargeBodyIsCountedInTheBudgetUntilItsCalculationAnswers) {
  HeldEngine held(1);
  Client client(held.engine());
  const std::string body(200 * 1024, 'b');
  client.send("POST /heavy HTTP/1.1\r\nHost: test\r\nX-Tag: body\r\nContent-Length: " +
              std::to_string(body.size()) + "\r\n\r\n" + body);
  ASSERT_TRUE(held.gate().wait_inside(1));
  EXPECT_EQ(held.engine().memory_budget().used(), kLargeBodyHeldTimes * body.size());
  held.gate().open();
  const testing::ParsedResponses answered = client.read_responses(1);
  ASSERT_EQ(answered.finals(), 1U) << client.bytes();
  EXPECT_EQ(answered.responses[0].body, "heavy body");
  ASSERT_TRUE(eventually([&] { return held.engine().memory_budget().used() == 0; }));
}

// The largest body a route takes may fill the budget alone: its own charge neither refuses its
// calculation nor the answer that replaces it.
TEST(CalculationPool, BodyThatFillsTheBudgetAloneIsCalculatedAndAnswered) {
  HeldEngine held(1, std::chrono::seconds(60), kSmallBudgetBytes);
  held.gate().open();
  Client client(held.engine());
  const std::string body(kSmallBudgetBytes / kLargeBodyHeldTimes, 'b');
  client.send("POST /heavy HTTP/1.1\r\nHost: test\r\nX-Tag: whole\r\nContent-Length: " +
              std::to_string(body.size()) + "\r\n\r\n" + body);
  const testing::ParsedResponses answered = client.read_responses(1);
  ASSERT_EQ(answered.finals(), 1U) << client.bytes();
  EXPECT_EQ(answered.responses[0].status, 200) << answered.responses[0].body;
  EXPECT_EQ(answered.responses[0].body, "heavy whole");
  EXPECT_EQ(held.counters().memory_refused.load(), 0U);
  ASSERT_TRUE(eventually([&] { return held.engine().memory_budget().used() == 0; }));
}

TEST(CalculationPool, HeadOfADeferredRequestHasContentLengthButNoBody) {
  HeldEngine held(1);
  held.gate().open();
  Client client(held.engine());
  client.send(request("HEAD", "/heavy", "X-Tag: h\r\n") +
              request("GET", "/light", "Connection: close\r\n"));
  ASSERT_TRUE(client.read_to_close()) << client.bytes();
  const testing::ParsedResponses answered = testing::parse_responses(client.bytes());
  ASSERT_FALSE(answered.error) << *answered.error;
  ASSERT_EQ(answered.finals(), 2U) << client.bytes();
  EXPECT_EQ(answered.responses[0].header("content-length"),
            std::to_string(std::string("heavy h").size()));
  EXPECT_EQ(answered.responses[0].body, "");
  EXPECT_EQ(answered.responses[1].body, "light");
}

// The pool's jobs counter, from the real service's /metrics.
std::uint64_t pool_jobs() {
  const testing::JsonReply metrics = testing::get("/metrics");
  EXPECT_EQ(metrics.status, 200);
  std::smatch match;
  const std::regex line(R"((?:^|\n)cutcalc_calculation_pool_jobs_total (\d+))");
  if (!std::regex_search(metrics.body, match, line)) {
    ADD_FAILURE() << "no cutcalc_calculation_pool_jobs_total in /metrics";
    return 0;
  }
  return std::stoull(match[1].str());
}

// A request the reference file expects a 200 for.
std::string valid_request(const std::string& file) {
  const nlohmann::json reference = testing::load_reference(file);
  for (const nlohmann::json& test_case : reference.at("cases")) {
    if (test_case.at("expect").value("status", 0) == 200) return test_case.at("request").dump();
  }
  ADD_FAILURE() << "no 200 case in " << file;
  return "{}";
}

TEST(CalculationPool, ProgramsGoToThePoolAndOtherCalculationsStayOnTheLoop) {
  const std::string program = valid_request("polygon-hole.json");
  const std::string groove = valid_request("roughness-groove-wall.json");
  const std::uint64_t before = pool_jobs();
  ASSERT_EQ(testing::post("/v1/roughness/groove-wall", groove).status, 200);
  ASSERT_EQ(testing::post("/v1/roughness/groove-wall", groove).status, 200);
  EXPECT_EQ(pool_jobs(), before);
  ASSERT_EQ(testing::post("/v1/polygon-hole/gcode", program).status, 200);
  // The calculation, and the pieces of its program as they are sent.
  EXPECT_GE(pool_jobs(), before + 2);
}

}  // namespace
}  // namespace cutcalc::service
