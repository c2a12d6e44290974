// B1-B8 with the procedure of B.4, spec roughness.md (paper 001).

#include "domain/roughness/bore_milling.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "domain/roughness/bisector_root.h"
#include "domain/roughness/planetary_path.h"
#include "domain/roughness/units.h"

namespace cutcalc::domain::roughness {

namespace {

using detail::kUmPerMm;

DomainError feed_too_large(const char* detail) {
  return make_error(ErrorCode::bore_feed_too_large, detail);
}

// B1: eps = S / (2 pi Rc). 2 pi Rc overflows for Rc above 2.8e307 mm and would make eps 0; only
// there the quotient is taken in two steps (elsewhere it keeps eps = 1 exact at S = 2 pi Rc).
double orbit_rate(double S, double Rc) {
  const double circumference = 2.0 * std::numbers::pi * Rc;  // of the centre path
  return std::isfinite(circumference) ? S / circumference : (S / Rc) / (2.0 * std::numbers::pi);
}

// B5: R - |P| at the root without forming |P| (at R = 81 mm a cusp of 1.6e-5 mm would keep only
// about 9 digits). q is divided by R^2 so that no square of a length can overflow.
double cusp_height_mm(double R, double Rc, double r, double delta_star) {
  const double sin_half = std::sin(0.5 * delta_star);                       // sin(delta*/2)
  const double q_over_R2 = 4.0 * (Rc / R) * (r / R) * sin_half * sin_half;  // q / R^2
  return R * q_over_R2 / (1.0 + std::sqrt(std::max(1.0 - q_over_R2, 0.0)));
}

// What B.4 steps 2-4 establish for an accepted feed: the path and the bracket [0, hi] of its root.
struct RootBracket {
  detail::PlanetaryPath path;
  double k = 0.0;           // k (B3)
  double half_alpha = 0.0;  // alpha/2 (B3)
  double s = 0.0;           // s (B6)
  double hi = 0.0;          // hi (B7)
};

// B.4 steps 2-4 for R > r: the bracket of the root, or why the feed is too large.
Result<RootBracket> bracket_root(double R, double r, double n, double S, double m) {
  const double Rc = R - r;               // Rc (B1)
  const double eps = orbit_rate(S, Rc);  // eps (B1)

  // B.4 step 2
  if (eps >= 1.0) {
    return feed_too_large(
        "the feed per revolution is too large: the cutter centre would orbit the bore at least "
        "once per spindle revolution");
  }
  // alpha >= 180 deg, i.e. 2 pi |k| / n >= pi, multiplied out so that no division rounds across
  // the limit.
  if (2.0 * eps >= n * std::abs(m - eps)) {
    return feed_too_large(
        "the feed per tooth is too large: successive teeth would meet the bore 180 degrees or "
        "more apart");
  }
  const double k = eps / (m - eps);                              // k (B3)
  const double half_alpha = std::numbers::pi * std::abs(k) / n;  // alpha/2 (B3)

  // B.4 step 3
  const double theta_prime_0 = k + r / R;  // theta'(0) (B6)
  if (theta_prime_0 == 0.0) {
    return feed_too_large(
        "in down-milling a feed per revolution equal to the cutter circumference holds each tooth "
        "at rest on the bore: the tooth paths form no cusp");
  }
  const double s = theta_prime_0 > 0.0 ? 1.0 : -1.0;  // s (B6)

  // B.4 step 4
  const detail::PlanetaryPath path(Rc, r, k);
  const double hi = path.monotone_end(s);  // hi (B7)
  if (s * path.theta(hi) < half_alpha) {
    return feed_too_large(
        "the feed per tooth is too large for this cutter: adjacent tooth paths do not meet within "
        "90 degrees of tooth rotation");
  }
  return RootBracket{path, k, half_alpha, s, hi};
}

double milling_sign(MillingSense milling) { return milling == MillingSense::up ? 1.0 : -1.0; }

}  // namespace

// B.4 steps 1-4
bool bore_milling_feed_accepted(const BoreMillingParams& params) {
  return params.cutter_radius_mm < params.bore_radius_mm &&
         bracket_root(params.bore_radius_mm, params.cutter_radius_mm,
                      static_cast<double>(params.teeth), params.feed_per_rev_mm,
                      milling_sign(params.milling))
             .ok();
}

// B1-B8, B.4
Result<BoreMillingResult> compute_bore_milling_cusp(const BoreMillingParams& params) {
  const double R = params.bore_radius_mm;              // R
  const double r = params.cutter_radius_mm;            // r
  const double n = static_cast<double>(params.teeth);  // n
  const double S = params.feed_per_rev_mm;             // S_n
  const double m = milling_sign(params.milling);       // m

  // B.4 step 1
  if (!(r < R)) {
    return make_error(ErrorCode::cutter_not_smaller_than_bore);
  }
  const double Rc = R - r;  // Rc (B1)

  // B.4 steps 2-4
  const auto bracket = bracket_root(R, r, n, S, m);
  if (!bracket.ok()) {
    return bracket.error();
  }
  const auto& [path, k, half_alpha, s, hi] = bracket.value();

  // B.4 step 5
  const std::optional<detail::BisectorCrossing> root =
      detail::find_bisector_crossing(path, s, half_alpha, hi);
  if (!root) {
    return make_error(ErrorCode::not_converged,
                      "bore-milling cusp: the bracketed root on the bisector did not converge");
  }

  // B.4 steps 6-7
  const double f_z = S / n;            // f_z (B2)
  const double f_zb = f_z * (R / Rc);  // f_zb (B2)
  BoreMillingResult result;
  result.cusp_height_um = cusp_height_mm(R, Rc, r, root->delta) * kUmPerMm;  // Delta (B5)
  // B8: f_zb^2 Rc / (8 r R), free of the cancellation in 1/r - 1/R; f_zb / r stays below a few
  // units once step 4 has passed, so nothing overflows.
  result.approximate_cusp_height_um = 0.125 * f_zb * (f_zb / r) * (Rc / R) * kUmPerMm;
  result.feed_per_tooth_mm = f_z;
  result.feed_per_tooth_on_bore_mm = f_zb;
  result.pitch_angle_deg = 360.0 * std::abs(k) / n;  // alpha (B3)
  // Radii near the top of the double range could still overflow the micrometres.
  if (!std::isfinite(result.cusp_height_um) || !std::isfinite(result.approximate_cusp_height_um)) {
    return make_error(ErrorCode::not_converged,
                      "bore-milling cusp: a cusp height exceeds the range of a double");
  }
  return result;
}

}  // namespace cutcalc::domain::roughness
