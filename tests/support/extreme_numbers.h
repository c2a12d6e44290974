#pragma once
// Numbers for the robustness tests of an endpoint: a quarter of them from a list of extremes
// (zero, denormal-small, negative, huge), the rest log-uniform in 1e-3..1e3; seeded, so a run is
// the same every time.

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <random>
#include <vector>

namespace cutcalc::testing {

class ExtremeNumbers {
 public:
  ExtremeNumbers(std::uint64_t seed, std::initializer_list<double> extremes)
      : engine_(seed), extremes_(extremes) {}

  double any() {
    if (pick(4) == 0)
      return extremes_[static_cast<std::size_t>(pick(static_cast<int>(extremes_.size())))];
    return std::pow(10.0, uniform(-3.0, 3.0));
  }
  // 0..n-1
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(engine_); }
  double uniform(double low, double high) {
    return std::uniform_real_distribution<double>(low, high)(engine_);
  }

 private:
  std::mt19937_64 engine_;
  std::vector<double> extremes_;
};

}  // namespace cutcalc::testing
