#include "support/service_process.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <regex>
#include <stdexcept>
#include <thread>

#include "support/http_responses.h"

namespace cutcalc::testing {

ServiceProcess::ServiceProcess(const std::string& binary, std::vector<std::string> args) {
  int pipe_fds[2];
  if (pipe(pipe_fds) != 0) {
    throw std::runtime_error("pipe failed");
  }
  args.insert(args.begin(), {binary, "--host", "127.0.0.1", "--port", "0"});
  pid_ = fork();
  if (pid_ == 0) {
    dup2(pipe_fds[1], STDOUT_FILENO);
    close(pipe_fds[0]);
    close(pipe_fds[1]);
    std::vector<char*> argv;
    for (std::string& arg : args) {
      argv.push_back(arg.data());
    }
    argv.push_back(nullptr);
    execv(binary.c_str(), argv.data());
    _exit(127);
  }
  close(pipe_fds[1]);
  stdout_fd_ = pipe_fds[0];
  fcntl(stdout_fd_, F_SETFL, O_NONBLOCK);
  const std::regex listening(R"(listening on http://127\.0\.0\.1:(\d+))");
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (std::chrono::steady_clock::now() < deadline) {
    std::smatch match;
    const std::string text = output();
    if (std::regex_search(text, match, listening)) {
      port_ = std::stoi(match[1].str());
      return;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  throw std::runtime_error("cutcalc did not report its port; output: " + output_);
}

ServiceProcess::~ServiceProcess() {
  if (!exited_ && pid_ > 0) {
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
  }
  if (stdout_fd_ >= 0) {
    close(stdout_fd_);
  }
}

void ServiceProcess::signal(int signal_number) const { kill(pid_, signal_number); }

int ServiceProcess::wait_exit(int timeout_ms) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
  while (std::chrono::steady_clock::now() < deadline) {
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      exited_ = true;
      output();
      return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return -1;
}

std::string ServiceProcess::output() {
  char buffer[4096];
  ssize_t got = 0;
  while ((got = read(stdout_fd_, buffer, sizeof buffer)) > 0) {
    output_.append(buffer, static_cast<std::size_t>(got));
  }
  return output_;
}

RawConnection::RawConnection(int port) {
  // Not inherited by a service process started while it is open.
  fd_ = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd_ < 0) {
    return;
  }
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (connect(fd_, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
    close(fd_);
    fd_ = -1;
  }
}

RawConnection::~RawConnection() {
  if (fd_ >= 0) {
    close(fd_);
  }
}

bool RawConnection::send_all(const std::string& bytes) {
  std::size_t sent = 0;
  while (sent < bytes.size()) {
    const ssize_t n = send(fd_, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
    if (n <= 0) {
      return false;
    }
    sent += static_cast<std::size_t>(n);
  }
  return true;
}

std::string RawConnection::read_all(int timeout_ms) {
  std::string out;
  char buffer[4096];
  pollfd ready{fd_, POLLIN, 0};
  while (poll(&ready, 1, timeout_ms) > 0) {
    const ssize_t n = recv(fd_, buffer, sizeof buffer, 0);
    if (n <= 0) {
      break;
    }
    out.append(buffer, static_cast<std::size_t>(n));
  }
  return out;
}

namespace {

// One recv() of what arrives within the time left; 0 when the peer closed, -1 on timeout.
ssize_t receive_some(int fd, std::string& into, std::chrono::steady_clock::time_point until) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
      until - std::chrono::steady_clock::now());
  pollfd ready{fd, POLLIN, 0};
  if (left.count() <= 0 || poll(&ready, 1, static_cast<int>(left.count())) <= 0) return -1;
  char buffer[65536];
  const ssize_t n = recv(fd, buffer, sizeof buffer, 0);
  if (n > 0) into.append(buffer, static_cast<std::size_t>(n));
  return n < 0 ? 0 : n;  // a reset counts as closed
}

}  // namespace

std::string RawConnection::read_responses(std::size_t finals, int timeout_ms) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
  std::string out;
  while (parse_responses(out).finals() < finals && receive_some(fd_, out, until) > 0) {
  }
  return out;
}

bool RawConnection::read_until_closed(int timeout_ms, std::string& into) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
  for (;;) {
    const ssize_t n = receive_some(fd_, into, until);
    if (n == 0) return true;
    if (n < 0) return false;
  }
}

RawConnection::PeerState RawConnection::peer_state() const {
  if (fd_ < 0) return PeerState::closed;
  char byte = 0;
  const ssize_t n = recv(fd_, &byte, 1, MSG_PEEK | MSG_DONTWAIT);
  if (n > 0) return PeerState::data;
  if (n == 0) return PeerState::closed;
  return errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR ? PeerState::silent
                                                                   : PeerState::closed;
}

bool RawConnection::drain_until_closed() {
  if (fd_ < 0) return true;
  for (;;) {
    char buffer[4096];
    const ssize_t n = recv(fd_, buffer, sizeof buffer, MSG_DONTWAIT);
    if (n == 0) return true;
    if (n < 0) return errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR;
  }
}

}  // namespace cutcalc::testing
