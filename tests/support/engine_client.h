// The client's end of a socketpair an EventLoopEngine adopted: byte-level tests of the engine
// without a listening socket or a process.
#pragma once

#include <chrono>
#include <string>

#include "service/http_event_loop.h"
#include "support/http_responses.h"

namespace cutcalc::testing {

// The settings of an engine for byte-level tests: one loop and a pool of `pool_threads` at the
// test's own priority; every limit at its default.
service::EventLoopSettings small_engine_settings(std::size_t pool_threads = 1);

// An engine error as a bare response with its status, for the tests that build their own engine.
std::string bare_engine_error(const service::EngineError& error);

class EngineClient {
 public:
  explicit EngineClient(service::EventLoopEngine& engine);
  ~EngineClient() { close(); }
  EngineClient(const EngineClient&) = delete;
  EngineClient& operator=(const EngineClient&) = delete;

  [[nodiscard]] int server_fd() const { return server_fd_; }
  void close();
  void shut_down_writing() const;
  // All of `bytes`, however many writes it takes (a gtest failure if the engine closed).
  void send(const std::string& bytes) const;
  // Reads until `finals` well-framed final responses are in, the peer closes, or the safety net
  // (kPatience) is hit.
  ParsedResponses read_responses(std::size_t finals);
  // Reads until the peer closes; false when the safety net is hit first.
  bool read_to_close();
  // Reads `bytes` at most, then waits `pause`, until the peer closes.
  void read_slowly(std::size_t bytes, std::chrono::milliseconds pause);
  // Whatever has arrived without waiting.
  const std::string& arrived_now();
  [[nodiscard]] const std::string& bytes() const { return bytes_; }

  // A safety net against a hang only; no test measures time.
  static constexpr std::chrono::seconds kPatience{10};

 private:
  // False on close, error or nothing within `timeout_ms`.
  bool read_some(int timeout_ms, std::size_t at_most = 65536);

  int fd_ = -1;
  int server_fd_ = -1;
  std::string bytes_;
  bool closed_ = false;
};

}  // namespace cutcalc::testing
