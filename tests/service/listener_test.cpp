// The listener: a port another socket listens on is an error that says so (no silent sharing),
// unless both sides ask for sharing; and the process started on a taken port exits non-zero.

#include "service/listener.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <future>
#include <string>
#include <thread>
#include <vector>

#include "service/unique_fd.h"

namespace cutcalc::service {
namespace {

// A safety net against a hang only; no test measures time.
constexpr auto kListenerPatience = std::chrono::seconds(10);

ListenSettings loopback(int port, bool reuse_port = false) {
  ListenSettings settings;
  settings.host = "127.0.0.1";
  settings.port = port;
  settings.reuse_port = reuse_port;
  return settings;
}

// A plain socket listening on a free loopback port, as another program would hold it; with
// `reuse_port` as a server that shares its port (an old cutcalc did) would.
struct PortHolder {
  explicit PortHolder(bool reuse_port) : sock(::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0)) {
    const int on = 1;
    if (reuse_port) ::setsockopt(sock.get(), SOL_SOCKET, SO_REUSEPORT, &on, sizeof(on));
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof(address);
    if (::bind(sock.get(), reinterpret_cast<sockaddr*>(&address), sizeof(address)) == 0 &&
        ::listen(sock.get(), 4) == 0 &&
        ::getsockname(sock.get(), reinterpret_cast<sockaddr*>(&address), &length) == 0) {
      port = ntohs(address.sin_port);
    }
  }
  UniqueFd sock;
  int port = -1;
};

bool connects(int port) {
  const UniqueFd sock(::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0));
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  return ::connect(sock.get(), reinterpret_cast<sockaddr*>(&address), sizeof(address)) == 0;
}

void expect_in_use_error(const std::string& error) {
  EXPECT_NE(error.find("already in use"), std::string::npos) << error;
  EXPECT_NE(error.find("--reuse-port"), std::string::npos) << error;
}

TEST(Listener, PortAnotherSocketListensOnIsAnErrorSayingSo) {
  for (const bool holder_shares : {false, true}) {
    const PortHolder holder(holder_shares);
    ASSERT_GT(holder.port, 0);
    Listener listener;
    EXPECT_EQ(listener.open(loopback(holder.port)), -1) << "holder shares: " << holder_shares;
    expect_in_use_error(listener.error());
  }
}

TEST(Listener, SecondListenerOnAServedPortFailsWithoutReusePort) {
  Listener first;
  const int port = first.open(loopback(0));
  ASSERT_GT(port, 0) << first.error();
  Listener second;
  EXPECT_EQ(second.open(loopback(port)), -1);
  expect_in_use_error(second.error());
}

TEST(Listener, ReusePortOnBothSharesThePort) {
  Listener first;
  const int port = first.open(loopback(0, true));
  ASSERT_GT(port, 0) << first.error();
  Listener second;
  EXPECT_EQ(second.open(loopback(port, true)), port) << second.error();
  EXPECT_TRUE(second.error().empty()) << second.error();
}

TEST(Listener, PortZeroGivesAFreePortThatAccepts) {
  Listener listener;
  const int port = listener.open(loopback(0));
  ASSERT_GT(port, 0) << listener.error();
  EXPECT_TRUE(connects(port));
}

TEST(Listener, StopBeforeRunMakesRunReturnAtOnce) {
  Listener listener;
  ASSERT_GT(listener.open(loopback(0)), 0) << listener.error();
  listener.stop();
  std::promise<bool> returned;
  std::thread running([&] { returned.set_value(listener.run([](int sock) { ::close(sock); })); });
  auto result = returned.get_future();
  if (result.wait_for(kListenerPatience) != std::future_status::ready) {
    ADD_FAILURE() << "run() did not return after an earlier stop()";
    listener.stop();  // unblock it, so the test ends
  }
  running.join();
  EXPECT_TRUE(result.get());
  EXPECT_TRUE(listener.stopped());
}

TEST(Listener, RunHandsAcceptedConnectionsOverUntilStopped) {
  Listener listener;
  const int port = listener.open(loopback(0));
  ASSERT_GT(port, 0) << listener.error();
  std::promise<void> adopted;
  std::atomic<int> count{0};
  std::thread running([&] {
    listener.run([&](int sock) {
      ::close(sock);
      if (count.fetch_add(1) == 0) adopted.set_value();
    });
  });
  EXPECT_TRUE(connects(port));
  EXPECT_EQ(adopted.get_future().wait_for(kListenerPatience), std::future_status::ready);
  listener.stop();
  running.join();
  EXPECT_FALSE(connects(port)) << "the listening socket is still open after run() returned";
}

TEST(Listener, RunWithoutOpenReturnsFalse) {
  Listener listener;
  EXPECT_FALSE(listener.run([](int sock) { ::close(sock); }));
}

struct Exit {
  int code = -1;       // -1: killed by a signal, or still running when the safety net was hit
  std::string output;  // stdout and stderr
};

// Runs the cutcalc binary with `args` to its end.
Exit run_cutcalc(const std::vector<std::string>& args) {
  int pipe_fds[2];
  if (::pipe2(pipe_fds, O_CLOEXEC) != 0) return {};
  std::vector<std::string> argv_text{CUTCALC_BINARY};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::dup2(pipe_fds[1], STDOUT_FILENO);
    ::dup2(pipe_fds[1], STDERR_FILENO);
    std::vector<char*> argv;
    for (std::string& arg : argv_text) argv.push_back(arg.data());
    argv.push_back(nullptr);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  ::close(pipe_fds[1]);
  Exit exit;
  const auto until = std::chrono::steady_clock::now() + kListenerPatience;
  char buffer[4096];
  for (;;) {  // to EOF: the process (and any thread of it) has ended
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        until - std::chrono::steady_clock::now());
    pollfd watched{pipe_fds[0], POLLIN, 0};
    if (left.count() <= 0 || ::poll(&watched, 1, static_cast<int>(left.count())) <= 0) {
      ::kill(pid, SIGKILL);
      break;
    }
    const ssize_t n = ::read(pipe_fds[0], buffer, sizeof(buffer));
    if (n <= 0) break;
    exit.output.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(pipe_fds[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (WIFEXITED(status)) exit.code = WEXITSTATUS(status);
  return exit;
}

TEST(Listener, ServiceOnATakenPortExitsNonZeroSayingSo) {
  const PortHolder holder(true);  // as an older cutcalc that shared its port would hold it
  ASSERT_GT(holder.port, 0);
  const Exit exit = run_cutcalc({"--host", "127.0.0.1", "--port", std::to_string(holder.port)});
  EXPECT_GT(exit.code, 0) << exit.output;
  EXPECT_NE(exit.output.find("already in use"), std::string::npos) << exit.output;
}

}  // namespace
}  // namespace cutcalc::service
