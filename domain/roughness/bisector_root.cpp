// B.4 step 5 of spec roughness.md: Newton with theta' (B6), safeguarded by bisection.

#include "domain/roughness/bisector_root.h"

#include <cmath>

namespace cutcalc::domain::roughness::detail {

namespace {

// Relative resolution of the stopping rules of B.4 step 5: two ulps of delta.
constexpr double kRelativeStop = 4e-16;

}  // namespace

// B.4 step 5
std::optional<BisectorCrossing> find_bisector_crossing(const PlanetaryPath& path, double s,
                                                       double half_alpha, double hi) {
  double lo = 0.0;
  // Near the contact theta is almost linear, so the first Newton step from 0 is the usual start.
  double delta = half_alpha / (s * path.theta_prime(0.0));  // delta_0
  // Never negative (s makes s theta'(0) > 0); a vanishing theta'(0) can make it infinite.
  if (!(delta < hi)) {
    delta = hi;
  }
  for (int iteration = 1; iteration <= kMaxBisectorIterations; ++iteration) {
    const double f = s * path.theta(delta) - half_alpha;  // f(delta)
    if (f == 0.0) {
      return BisectorCrossing{delta, iteration};
    }
    // f is increasing on the bracket (B7), so its sign says on which side the root lies.
    if (f < 0.0) {
      lo = delta;
    } else {
      hi = delta;
    }
    if (hi - lo <= kRelativeStop * hi) {
      return BisectorCrossing{delta, iteration};
    }
    const double newton_step = -f / (s * path.theta_prime(delta));
    // Tested before the bracket: a step below the resolution rounds next onto delta, an end of
    // the bracket, and would otherwise send a converged iterate into some 50 bisections.
    if (std::abs(newton_step) <= kRelativeStop * delta) {
      return BisectorCrossing{delta + newton_step, iteration};
    }
    double next = delta + newton_step;
    // Newton may overshoot where theta' flattens towards delta_m; the bracket never does.
    if (!(next > lo && next < hi)) {
      next = lo + 0.5 * (hi - lo);
      // Adjacent doubles (possible only for subnormal brackets): nothing lies between them.
      if (next == lo || next == hi) {
        return BisectorCrossing{next, iteration};
      }
    }
    const double step = next - delta;
    delta = next;
    if (std::abs(step) <= kRelativeStop * delta) {
      return BisectorCrossing{delta, iteration};
    }
  }
  return std::nullopt;
}

}  // namespace cutcalc::domain::roughness::detail
