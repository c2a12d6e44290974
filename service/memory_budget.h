#pragma once
// The memory the requests in flight may hold besides their connections' own buffers (README.md,
// "Running"): bodies above the default limit while they are received and until their calculation
// has answered, and answers waiting for their clients to read them. Work that would go past it is
// refused with 503 and Retry-After before it holds anything: a large body before it is read, a
// calculation before it is handed to the pool. What is held already (a computed answer) is
// counted even past the capacity, and new work waits until it drains.

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <utility>

namespace cutcalc::service {

class MemoryBudget {
 public:
  explicit MemoryBudget(std::uint64_t capacity_bytes) : capacity_(capacity_bytes) {}
  MemoryBudget(const MemoryBudget&) = delete;
  MemoryBudget& operator=(const MemoryBudget&) = delete;

  // Takes `bytes` when they fit under the capacity; false, and nothing taken, otherwise.
  bool try_take(std::uint64_t bytes) {
    std::uint64_t now = used_.load(std::memory_order_relaxed);
    do {
      if (bytes > capacity_ || now > capacity_ - bytes) return false;
    } while (!used_.compare_exchange_weak(now, now + bytes, std::memory_order_relaxed));
    return true;
  }
  // Counts bytes that are held already, past the capacity if need be.
  void take(std::uint64_t bytes) { used_.fetch_add(bytes, std::memory_order_relaxed); }
  void give_back(std::uint64_t bytes) { used_.fetch_sub(bytes, std::memory_order_relaxed); }

  // No new work fits: what is held has reached the capacity.
  [[nodiscard]] bool spent() const { return used_.load(std::memory_order_relaxed) >= capacity_; }
  // As spent(), not counting `own` bytes held for the work itself (its body): a body that fills
  // the budget alone does not keep its own calculation from running.
  [[nodiscard]] bool spent_besides(std::uint64_t own) const {
    const std::uint64_t used = used_.load(std::memory_order_relaxed);
    return used - std::min(used, own) >= capacity_;
  }
  [[nodiscard]] std::uint64_t used() const { return used_.load(std::memory_order_relaxed); }
  [[nodiscard]] std::uint64_t capacity() const { return capacity_; }

 private:
  const std::uint64_t capacity_;
  std::atomic<std::uint64_t> used_{0};
};

// Bytes taken from the budget on one thread and handed to another (a computed answer on its way
// from the pool to its connection): given back if nobody takes them over.
class BudgetLease {
 public:
  BudgetLease() = default;
  BudgetLease(MemoryBudget& budget, std::uint64_t bytes) : budget_(&budget), bytes_(bytes) {}
  BudgetLease(BudgetLease&& other) noexcept
      : budget_(std::exchange(other.budget_, nullptr)), bytes_(std::exchange(other.bytes_, 0)) {}
  BudgetLease& operator=(BudgetLease&& other) noexcept {
    if (this != &other) {
      reset();
      budget_ = std::exchange(other.budget_, nullptr);
      bytes_ = std::exchange(other.bytes_, 0);
    }
    return *this;
  }
  BudgetLease(const BudgetLease&) = delete;
  BudgetLease& operator=(const BudgetLease&) = delete;
  ~BudgetLease() { reset(); }

  // The bytes, for a new holder that counts them from now on.
  std::uint64_t release() {
    budget_ = nullptr;
    return std::exchange(bytes_, 0);
  }

 private:
  void reset() {
    if (budget_ != nullptr) budget_->give_back(bytes_);
    budget_ = nullptr;
    bytes_ = 0;
  }
  MemoryBudget* budget_ = nullptr;
  std::uint64_t bytes_ = 0;
};

// What one connection has counted in the budget; gives it back when the connection goes.
class BudgetCharge {
 public:
  explicit BudgetCharge(MemoryBudget& budget) : budget_(budget) {}
  BudgetCharge(const BudgetCharge&) = delete;
  BudgetCharge& operator=(const BudgetCharge&) = delete;
  ~BudgetCharge() { budget_.give_back(bytes_); }

  // Counts `bytes` more if they fit; false otherwise.
  bool try_add(std::uint64_t bytes) {
    if (!budget_.try_take(bytes)) return false;
    bytes_ += bytes;
    return true;
  }
  // Counts bytes taken already (a lease's) as this charge's.
  void adopt(std::uint64_t bytes) { bytes_ += bytes; }
  // Makes the charge `bytes` (held already: never refused).
  void set(std::uint64_t bytes) {
    if (bytes > bytes_) budget_.take(bytes - bytes_);
    if (bytes < bytes_) budget_.give_back(bytes_ - bytes);
    bytes_ = bytes;
  }
  [[nodiscard]] std::uint64_t bytes() const { return bytes_; }

 private:
  MemoryBudget& budget_;
  std::uint64_t bytes_ = 0;
};

}  // namespace cutcalc::service
