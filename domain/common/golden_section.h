#pragma once
// Golden-section search for the extremum of a unimodal function on a bracket, shared by the
// polygon-hole refinements (P17, P21, P24) and the tests' exact path.

#include <algorithm>
#include <cmath>

namespace cutcalc::domain {

// The last bracket [a, b] and its two inner points x1 < x2 with their values.
struct GoldenSection {
  double a = 0.0;
  double b = 0.0;
  double x1 = 0.0;
  double f1 = 0.0;
  double x2 = 0.0;
  double f2 = 0.0;

  [[nodiscard]] double midpoint() const { return 0.5 * (a + b); }
  [[nodiscard]] double smallest_value() const { return std::min(f1, f2); }
};

// Minimum of f on [a, b]: each step keeps the part of the bracket holding the smaller inner value
// (the right part on a tie), so the bracket shrinks by (sqrt5 - 1) / 2 per evaluation of f. Stops
// once b - a <= width or after max_iterations steps.
template <class F>
GoldenSection golden_section_minimum(const F& f, double a, double b, double width,
                                     int max_iterations) {
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  GoldenSection s{a, b, b - ratio * (b - a), 0.0, a + ratio * (b - a), 0.0};
  s.f1 = f(s.x1);
  s.f2 = f(s.x2);
  for (int iteration = 0; iteration < max_iterations && s.b - s.a > width; ++iteration) {
    if (s.f1 < s.f2) {
      s.b = s.x2;
      s.x2 = s.x1;
      s.f2 = s.f1;
      s.x1 = s.b - ratio * (s.b - s.a);
      s.f1 = f(s.x1);
    } else {
      s.a = s.x1;
      s.x1 = s.x2;
      s.f1 = s.f2;
      s.x2 = s.a + ratio * (s.b - s.a);
      s.f2 = f(s.x2);
    }
  }
  return s;
}

}  // namespace cutcalc::domain
