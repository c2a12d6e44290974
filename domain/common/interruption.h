#pragma once
// Stopping a long calculation from outside: its client has gone, or its deadline passed. The caller
// lends the calculating thread a stop flag for the calculation's duration (InterruptionScope); the
// long loops (a program's blocks, a timed program's lines) call interruption_point(), which throws
// Interrupted once the flag is set. Boost.Thread's interruption points are the model: a check costs
// a thread-local load and a relaxed atomic load, and a calculation nobody stops never notices.
//
// Interrupted is deliberately not a std::exception: whoever catches std::exception to answer a
// bug with a 500 lets it pass, and whoever set the flag has answered the request already.

#include <atomic>

namespace cutcalc::domain {

struct Interrupted {};

class InterruptionScope {
 public:
  explicit InterruptionScope(const std::atomic<bool>& stop) noexcept;
  ~InterruptionScope();
  InterruptionScope(const InterruptionScope&) = delete;
  InterruptionScope& operator=(const InterruptionScope&) = delete;

 private:
  const std::atomic<bool>* previous_;
};

// Throws Interrupted when this thread's calculation was asked to stop.
void interruption_point();

}  // namespace cutcalc::domain
