#include "service/signals.h"

#include <pthread.h>
#include <csignal>

namespace cutcalc::service {
namespace {

sigset_t shutdown_set() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGTERM);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGUSR2);  // internal: wakes the waiter when the process ends on its own
  return set;
}

}  // namespace

ShutdownSignals::ShutdownSignals() {
  const sigset_t set = shutdown_set();
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
  // A peer closing a keep-alive socket mid-write must not kill the process.
  std::signal(SIGPIPE, SIG_IGN);
}

ShutdownSignals::~ShutdownSignals() {
  if (waiter_.joinable()) {
    pthread_kill(waiter_.native_handle(), SIGUSR2);
    waiter_.join();
  }
}

void ShutdownSignals::on_shutdown(std::function<void(const char* signal_name)> on_signal) {
  waiter_ = std::thread([on_signal = std::move(on_signal)] {
    const sigset_t set = shutdown_set();
    int received = 0;
    if (sigwait(&set, &received) != 0 || received == SIGUSR2) {
      return;
    }
    on_signal(received == SIGTERM ? "SIGTERM" : "SIGINT");
  });
}

}  // namespace cutcalc::service
