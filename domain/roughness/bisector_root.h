#pragma once
// The root of B.4 step 5 of spec roughness.md: where one tooth path reaches the bisector ray
// between its contact with the bore and the next tooth's. Private to domain/roughness.

#include <optional>

#include "domain/roughness/planetary_path.h"

namespace cutcalc::domain::roughness::detail {

struct BisectorCrossing {
  double delta = 0.0;  // delta*: s theta(delta*) = alpha/2
  int iterations = 0;  // evaluations of f, for the tests and benchmarks
};

// Safeguarded Newton iterations cannot exceed this on a bracketed root: bisection alone needs
// about 60-80 halvings (B.4 step 5).
inline constexpr int kMaxBisectorIterations = 200;

// B.4 step 5: the root of f(delta) = s theta(delta) - alpha/2 on [0, hi], given f(0) <= 0 <= f(hi)
// and s theta increasing there (B7). Nothing when the cap is reached: a bug, never a guess.
std::optional<BisectorCrossing> find_bisector_crossing(const PlanetaryPath& path, double s,
                                                       double half_alpha, double hi);

}  // namespace cutcalc::domain::roughness::detail
