#include "domain/common/interruption.h"

namespace cutcalc::domain {
namespace {

thread_local const std::atomic<bool>* t_stop = nullptr;

}  // namespace

InterruptionScope::InterruptionScope(const std::atomic<bool>& stop) noexcept : previous_(t_stop) {
  t_stop = &stop;
}

InterruptionScope::~InterruptionScope() { t_stop = previous_; }

void interruption_point() {
  if (t_stop != nullptr && t_stop->load(std::memory_order_relaxed)) throw Interrupted{};
}

}  // namespace cutcalc::domain
