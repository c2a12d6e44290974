#pragma once
// The planner's look-ahead queue: a fixed ring of segments (LinuxCNC's tcq, tcq.c). It never
// allocates, and an element stays where it is while others are added and removed around it.

#include <array>
#include <cstddef>
#include <utility>

#include "domain/machine_time/segment.h"

namespace cutcalc::domain::machine_time {

template <std::size_t Capacity>
class SegmentRing {
  static_assert((Capacity & (Capacity - 1)) == 0, "a power of two");

 public:
  [[nodiscard]] bool empty() const { return size_ == 0; }
  [[nodiscard]] std::size_t size() const { return size_; }
  Segment& operator[](std::size_t i) { return slots_[(head_ + i) & kMask]; }
  Segment& front() { return slots_[head_]; }
  Segment& back() { return (*this)[size_ - 1]; }

  // The caller keeps size() below Capacity (the planner runs what it no longer changes).
  void push_back(Segment segment) {
    (*this)[size_] = std::move(segment);
    ++size_;
  }
  void pop_back() { --size_; }
  Segment take_front() {
    Segment segment = std::move(slots_[head_]);
    head_ = (head_ + 1) & kMask;
    --size_;
    return segment;
  }

 private:
  static constexpr std::size_t kMask = Capacity - 1;
  std::array<Segment, Capacity> slots_{};
  std::size_t head_ = 0;
  std::size_t size_ = 0;
};

}  // namespace cutcalc::domain::machine_time
