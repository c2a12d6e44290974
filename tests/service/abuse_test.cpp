// Abuse: slow and idle clients must not starve others.
//
// IdleAndSlowlorisClientsDoNotStarveOthers: with 300 idle keep-alive connections (each made one
// request) and 50 slowloris connections (a request head sent one byte a second) open at once,
// requests on fresh connections are answered 200 within 1 s each; the idle connections are then
// closed by the keep-alive timeout (5 s here, 75 s by default), the slowloris ones by the
// request deadline (10 s from their first byte), and the server still answers within 1 s
// afterwards.
//
// A stop with many requests in flight: restart_test.cpp (Restart.SigtermWithRequestsInFlight...).

#include <poll.h>
#include <sys/resource.h>
#include <sys/socket.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <utility>
#include <vector>

#include "support/http_responses.h"
#include "support/service_process.h"

namespace cutcalc::testing {
namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

constexpr int kIdleConnections = 300;
constexpr int kSlowlorisConnections = 50;
constexpr milliseconds kAnswerWithin{1000};
// The server's defaults (service/http_tuning.h).
constexpr milliseconds kKeepAliveTimeout{5000};
constexpr milliseconds kRequestDeadline{10000};
constexpr short kReadable = POLLIN | POLLRDHUP;

const std::string kEntryBody =
    R"({"cutter_diameter_mm": 20, "offset_mm": 0, "entry": {"contour": "straight", "width_mm": 60, "angle_deg": 90}})";

std::string entry_length_request(std::string_view body) {
  return "POST /v1/entry-length HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
         "Content-Length: " +
         std::to_string(body.size()) + "\r\n\r\n" + std::string(body);
}

double to_ms(Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); }

// Raises the soft RLIMIT_NOFILE of this process (and so of the server it forks later) to the
// hard limit; if even that is below `needed`, tries to raise both (root may). Empty on success.
std::string ensure_fd_limit(rlim_t needed) {
  rlimit limit{};
  if (getrlimit(RLIMIT_NOFILE, &limit) != 0) return "getrlimit failed";
  if (limit.rlim_cur != RLIM_INFINITY && limit.rlim_cur < limit.rlim_max) {
    rlimit raised = limit;
    raised.rlim_cur = limit.rlim_max;
    if (setrlimit(RLIMIT_NOFILE, &raised) == 0) limit = raised;
  }
  if (limit.rlim_cur == RLIM_INFINITY || limit.rlim_cur >= needed) return {};
  const rlimit wanted{needed, needed};
  if (setrlimit(RLIMIT_NOFILE, &wanted) == 0) return {};
  return "RLIMIT_NOFILE hard limit " + std::to_string(limit.rlim_max) + " is below the " +
         std::to_string(needed) + " descriptors this test needs (ulimit -Hn)";
}

// One whole response on `connection` within `timeout`; nullopt when none is complete by then or
// the peer closed first.
std::optional<HttpResponse> read_response(RawConnection& connection, milliseconds timeout) {
  const ParsedResponses parsed =
      parse_responses(connection.read_responses(1, static_cast<int>(timeout.count())));
  if (parsed.error || parsed.finals() != 1) return std::nullopt;
  return parsed.responses.back();
}

struct Timed {
  int status = 0;  // 0: no complete answer
  double ms = 0;
  std::string detail;
};

// POST /v1/entry-length on a fresh connection: status and time from connect() to the whole
// response.
Timed timed_request(int port, milliseconds give_up_after) {
  const auto start = Clock::now();
  RawConnection client(port);
  Timed timed;
  if (!client.connected()) {
    timed.detail = "connect failed";
  } else if (!client.send_all(entry_length_request(kEntryBody))) {
    timed.detail = "send failed";
  } else if (const auto response = read_response(client, give_up_after)) {
    timed.status = response->status;
    if (response->body.find("\"entry_length_mm\"") == std::string::npos) {
      timed.detail = "status " + std::to_string(response->status) + ": " + response->body;
    }
  } else {
    timed.detail = "no complete response";
  }
  timed.ms = to_ms(Clock::now() - start);
  return timed;
}

// `count` requests one after the other on fresh connections, `gap` apart; each must be answered
// 200 within kAnswerWithin. Returns the latencies.
std::vector<double> expect_prompt_answers(int port, int count, milliseconds gap,
                                          const char* phase) {
  std::vector<double> latencies;
  for (int i = 0; i < count; ++i) {
    const Timed timed = timed_request(port, milliseconds{5000});
    latencies.push_back(timed.ms);
    EXPECT_EQ(timed.status, 200) << phase << ", request " << i << ": " << timed.detail;
    EXPECT_TRUE(timed.detail.empty()) << phase << ", request " << i << ": " << timed.detail;
    EXPECT_LT(timed.ms, to_ms(kAnswerWithin)) << phase << ", request " << i;
    std::this_thread::sleep_for(gap);
  }
  return latencies;
}

std::string summary(std::vector<double> ms) {
  if (ms.empty()) return "none";
  std::sort(ms.begin(), ms.end());
  char text[128];
  std::snprintf(text, sizeof text, "n=%zu min %.1f ms, median %.1f ms, max %.1f ms", ms.size(),
                ms.front(), ms[ms.size() / 2], ms.back());
  return text;
}

// Sends the next byte of a never-ending request head to every connection, once a second, from a
// thread of its own. The first byte starts the server's request deadline.
class Slowloris {
 public:
  explicit Slowloris(std::vector<int> fds) : fds_(std::move(fds)) {
    thread_ = std::jthread([this](std::stop_token stop) { run(stop); });
  }
  ~Slowloris() {
    thread_.request_stop();
    if (thread_.joinable()) thread_.join();
  }
  Slowloris(const Slowloris&) = delete;
  Slowloris& operator=(const Slowloris&) = delete;

  // When the first byte went out to all of them (waits for it).
  Clock::time_point first_byte_sent() const {
    while (!started_.load()) std::this_thread::sleep_for(milliseconds{1});
    return first_byte_;
  }
  int bytes_sent() const { return bytes_sent_.load(); }

 private:
  void run(const std::stop_token& stop) {
    // Long enough never to complete within the deadline at one byte a second.
    const std::string head =
        "POST /v1/entry-length HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
        "X-Padding: slowloris-slowloris-slowloris-slowloris-slowloris\r\n";
    for (std::size_t i = 0; i < head.size() && !stop.stop_requested(); ++i) {
      for (const int fd : fds_) {
        [[maybe_unused]] const auto n = ::send(fd, &head[i], 1, MSG_NOSIGNAL | MSG_DONTWAIT);
      }
      if (i == 0) {
        first_byte_ = Clock::now();
        started_.store(true);
      }
      bytes_sent_.fetch_add(1);
      const auto next = Clock::now() + milliseconds{1000};
      while (Clock::now() < next && !stop.stop_requested()) {
        std::this_thread::sleep_for(milliseconds{20});
      }
    }
  }

  std::vector<int> fds_;
  Clock::time_point first_byte_{};
  std::atomic<bool> started_{false};
  std::atomic<int> bytes_sent_{0};
  std::jthread thread_;
};

TEST(Abuse, IdleAndSlowlorisClientsDoNotStarveOthers) {
  const std::string limit_problem = ensure_fd_limit(kIdleConnections + kSlowlorisConnections + 200);
  ASSERT_TRUE(limit_problem.empty()) << limit_problem;
  ServiceProcess service(CUTCALC_BINARY, {"--log-level", "info", "--keep-alive-timeout-s", "5"});
  const int port = service.port();
  std::vector<double> before = expect_prompt_answers(port, 3, milliseconds{0}, "warm-up");

  // Slowloris first (their deadline is the longer one): connected, then a byte a second.
  std::vector<std::unique_ptr<RawConnection>> slow;
  std::vector<int> slow_fds;
  for (int i = 0; i < kSlowlorisConnections; ++i) {
    slow.push_back(std::make_unique<RawConnection>(port));
    ASSERT_TRUE(slow.back()->connected()) << "slowloris connection " << i;
    slow_fds.push_back(slow.back()->fd());
  }
  Slowloris trickle(slow_fds);
  const Clock::time_point slow_start = trickle.first_byte_sent();

  // 300 keep-alive connections, each with one request answered, then idle.
  std::vector<std::unique_ptr<RawConnection>> idle;
  for (int i = 0; i < kIdleConnections; ++i) {
    idle.push_back(std::make_unique<RawConnection>(port));
    ASSERT_TRUE(idle.back()->connected())
        << "idle connection " << i << ": " << std::strerror(errno);
    ASSERT_TRUE(idle.back()->send_all(
        "GET /healthz HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: keep-alive\r\n\r\n"));
  }
  for (int i = 0; i < kIdleConnections; ++i) {
    const auto response = read_response(*idle[static_cast<std::size_t>(i)], milliseconds{5000});
    ASSERT_TRUE(response.has_value())
        << "idle connection " << i << ": no answer within 5 s (starved?)";
    ASSERT_EQ(response->status, 200) << response->body;
  }
  const Clock::time_point idle_since = Clock::now();
  service.output();  // keep the log pipe drained

  // The measurement: fresh connections while all 350 are open.
  const std::vector<double> during =
      expect_prompt_answers(port, 10, milliseconds{100}, "with idle and slowloris clients open");
  const Clock::time_point measured_until = Clock::now();
  ASSERT_LT(measured_until - idle_since, kKeepAliveTimeout - milliseconds{500})
      << "the measurement took too long to count as 'while the idle connections are open'";
  int idle_open = 0;
  for (const auto& client : idle)
    idle_open += client->peer_state() == RawConnection::PeerState::silent ? 1 : 0;
  int slow_open = 0;
  for (const auto& client : slow)
    slow_open += client->peer_state() == RawConnection::PeerState::silent ? 1 : 0;
  EXPECT_EQ(idle_open, kIdleConnections) << "idle keep-alive connections closed too early";
  EXPECT_EQ(slow_open, kSlowlorisConnections) << "slowloris connections closed or answered early";
  const int bytes_during = trickle.bytes_sent();

  // The idle connections go at the keep-alive timeout, the slowloris ones at the request deadline.
  std::vector<bool> idle_closed(idle.size(), false), slow_closed(slow.size(), false);
  std::size_t idle_left = idle.size(), slow_left = slow.size();
  Clock::time_point idle_all_closed{}, slow_first_closed{}, slow_all_closed{};
  const auto give_up = slow_start + kRequestDeadline + milliseconds{4000};
  while ((idle_left > 0 || slow_left > 0) && Clock::now() < give_up) {
    std::vector<pollfd> fds;
    std::vector<std::pair<bool, std::size_t>> which;  // (slowloris?, index)
    for (std::size_t i = 0; i < idle.size(); ++i) {
      if (!idle_closed[i]) {
        fds.push_back({idle[i]->fd(), kReadable, 0});
        which.emplace_back(false, i);
      }
    }
    for (std::size_t i = 0; i < slow.size(); ++i) {
      if (!slow_closed[i]) {
        fds.push_back({slow[i]->fd(), kReadable, 0});
        which.emplace_back(true, i);
      }
    }
    if (::poll(fds.data(), fds.size(), 200) <= 0) {
      service.output();
      continue;
    }
    const auto now = Clock::now();
    for (std::size_t k = 0; k < fds.size(); ++k) {
      if (fds[k].revents == 0) continue;
      auto& client = which[k].first ? slow[which[k].second] : idle[which[k].second];
      if (!client->drain_until_closed()) continue;
      if (which[k].first) {
        slow_closed[which[k].second] = true;
        if (slow_left == slow.size()) slow_first_closed = now;
        if (--slow_left == 0) slow_all_closed = now;
      } else {
        idle_closed[which[k].second] = true;
        if (--idle_left == 0) idle_all_closed = now;
      }
    }
  }
  EXPECT_EQ(idle_left, 0U) << "idle keep-alive connections still open "
                           << to_ms(Clock::now() - idle_since) << " ms after their request";
  ASSERT_EQ(slow_left, 0U) << "slowloris connections still open "
                           << to_ms(Clock::now() - slow_start) << " ms after their first byte";
  const double idle_cut_ms = to_ms(idle_all_closed - idle_since);
  const double slow_first_ms = to_ms(slow_first_closed - slow_start);
  const double slow_all_ms = to_ms(slow_all_closed - slow_start);
  // Cut by the deadline: not before it, and within a few sweeps after.
  EXPECT_GE(slow_first_ms, to_ms(kRequestDeadline) - 500);
  EXPECT_LE(slow_all_ms, to_ms(kRequestDeadline) + 3000);
  EXPECT_LE(idle_cut_ms, to_ms(kKeepAliveTimeout) + 3000);

  // And the server still serves.
  const std::vector<double> after =
      expect_prompt_answers(port, 5, milliseconds{50}, "after the slowloris connections were cut");
  service.output();

  const std::string report =
      "warm-up: " + summary(before) + "\nwith " + std::to_string(kIdleConnections) + " idle + " +
      std::to_string(kSlowlorisConnections) + " slowloris open (" + std::to_string(bytes_during) +
      " head bytes sent so far): " + summary(during) + "\nafter the cut: " + summary(after) +
      "\nidle connections all closed " + std::to_string(static_cast<int>(idle_cut_ms)) +
      " ms after their request; slowloris cut " + std::to_string(static_cast<int>(slow_first_ms)) +
      "-" + std::to_string(static_cast<int>(slow_all_ms)) + " ms after their first byte";
  std::printf("%s\n", report.c_str());
  ::testing::Test::RecordProperty("latencies", report);
}

}  // namespace
}  // namespace cutcalc::testing
