#pragma once
// The cutcalc executable as a child process on a free loopback port, for tests of process-level
// behaviour (signals, exit codes, log output).

#include <sys/types.h>

#include <cstddef>
#include <string>
#include <vector>

namespace cutcalc::testing {

class ServiceProcess {
 public:
  // Starts `binary` with `args` plus --host 127.0.0.1 --port 0 and waits for its listening line.
  explicit ServiceProcess(const std::string& binary, std::vector<std::string> args = {});
  ~ServiceProcess();
  ServiceProcess(const ServiceProcess&) = delete;
  ServiceProcess& operator=(const ServiceProcess&) = delete;

  [[nodiscard]] int port() const { return port_; }
  void signal(int signal_number) const;
  // Waits up to `timeout_ms` for exit; returns the exit code, or -1 on timeout / abnormal end.
  int wait_exit(int timeout_ms);
  // Everything the process wrote to stdout so far (reads what is available).
  std::string output();

 private:
  pid_t pid_ = -1;
  int stdout_fd_ = -1;
  int port_ = -1;
  std::string output_;
  bool exited_ = false;
};

// A raw TCP connection to 127.0.0.1:port, for requests sent in pieces and for clients that
// misbehave (idle, slow, never finishing a request).
class RawConnection {
 public:
  explicit RawConnection(int port);
  ~RawConnection();
  RawConnection(const RawConnection&) = delete;
  RawConnection& operator=(const RawConnection&) = delete;

  [[nodiscard]] bool connected() const { return fd_ >= 0; }
  bool send_all(const std::string& bytes);
  // Reads until the peer closes or `timeout_ms` passes without data.
  std::string read_all(int timeout_ms);
  // Reads until `finals` final responses (support/http_responses.h) are in, the peer closes or
  // `timeout_ms` passes in all.
  std::string read_responses(std::size_t finals, int timeout_ms);
  // Reads until the peer closes (true) or `timeout_ms` passes in all (false); appends to `into`.
  bool read_until_closed(int timeout_ms, std::string& into);
  [[nodiscard]] int fd() const { return fd_; }

  // Without blocking or reading: open and silent, closed by the peer (EOF or reset, or never
  // connected), or bytes waiting.
  enum class PeerState { silent, closed, data };
  [[nodiscard]] PeerState peer_state() const;
  // Without blocking: discards what the peer has sent; true once it has closed (EOF or reset).
  bool drain_until_closed();

 private:
  int fd_ = -1;
};

}  // namespace cutcalc::testing
