// B9-B12 of spec roughness.md addition B.9: bisections over the feed per revolution, each test one
// answer of B.4 (B11: the accepted feeds are (0, S_lim] and Delta rises on them, checked
// numerically; the bisections stay well defined without it: they end where their test changes).

#include "domain/roughness/bore_milling_feed.h"

#include <algorithm>
#include <numbers>
#include <optional>

namespace cutcalc::domain::roughness {

namespace {

// Halvings of [0, hi] until lo and hi are adjacent doubles: about 55 from a feed near hi, at most
// about 1100 down to the smallest double.
constexpr int kMaxHalvings = 2200;

// The last lo of a bisection on [lo, hi] with passes(lo) and !passes(hi): passes(mid) -> lo = mid,
// else hi = mid, until mid is lo or hi. Nothing when the cap is reached: a bug, never a guess.
template <class Test>
std::optional<double> last_passing(double lo, double hi, const Test& passes) {
  for (int i = 0; i < kMaxHalvings; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid == lo || mid == hi) {
      return lo;
    }
    (passes(mid) ? lo : hi) = mid;
  }
  return std::nullopt;
}

DomainError bisection_not_converged() {
  return make_error(ErrorCode::not_converged, "bore-milling feed: the bisection did not finish");
}

// Delta(S) in um, or nothing where B.4 refuses S.
std::optional<double> cusp_at(const BoreMillingParams& params, double S) {
  BoreMillingParams at = params;
  at.feed_per_rev_mm = S;
  const auto cusp = compute_bore_milling_cusp(at);
  return cusp.ok() ? std::optional(cusp.value().cusp_height_um) : std::nullopt;
}

}  // namespace

// B9, B10
double bore_milling_feed_limit_mm(const BoreMillingParams& params) {
  const double Rc = params.bore_radius_mm - params.cutter_radius_mm;  // Rc (B1)
  const double r = params.cutter_radius_mm;                           // r
  const double n = static_cast<double>(params.teeth);                 // n
  // B9: S_top, where eps = 1, alpha = 180 deg (up) or theta'(0) = 0 (down) is first reached.
  const double S_top = params.milling == MillingSense::up
                           ? 2.0 * std::numbers::pi * Rc * std::min(1.0, n / (n + 2.0))
                           : 2.0 * std::numbers::pi * std::min(Rc, r);
  BoreMillingParams at = params;
  const auto S_lim = last_passing(0.0, S_top, [&](double S) {
    at.feed_per_rev_mm = S;
    return bore_milling_feed_accepted(at);
  });
  // The cap cannot be reached with doubles; should it be, 0 is the one feed certainly accepted.
  return S_lim.value_or(0.0);
}

// B12
Result<double> bore_milling_max_feed_mm(const BoreMillingParams& params, double target_cusp_um) {
  const double T = target_cusp_um;                          // T
  const double S_lim = bore_milling_feed_limit_mm(params);  // S_lim (B10)
  const auto cusp_at_limit = cusp_at(params, S_lim);        // Delta(S_lim)
  if (!cusp_at_limit) {
    return bisection_not_converged();  // S_lim is accepted by construction
  }
  if (*cusp_at_limit < T) {
    return DomainError{ErrorCode::target_cusp_unreachable,
                       "every feed the model accepts leaves a cusp below the target", std::nullopt,
                       *cusp_at_limit};
  }
  if (*cusp_at_limit == T) {
    return S_lim;  // the supremum itself, one double above the bisection's last lo
  }
  const auto S_max = last_passing(0.0, S_lim, [&](double S) {
    const auto cusp = cusp_at(params, S);
    return cusp && *cusp <= T;
  });
  if (!S_max) {
    return bisection_not_converged();
  }
  return *S_max;
}

}  // namespace cutcalc::domain::roughness
