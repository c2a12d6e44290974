// Closed forms E13-E22 (shared/domain/entry-and-main-time.md section 6) as a test oracle.
#include "domain/entry/closed_forms.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cutcalc::test::entry_oracle {
namespace {

// sqrt(p^2 - q^2) as sqrt((p - q)(p + q)), clamped at 0 (spec section 5, numerics).
double root_diff(double p, double q) {
  const double product = (p - q) * (p + q);
  return product > 0.0 ? std::sqrt(product) : 0.0;
}

double radians(double deg) { return deg * (std::numbers::pi / 180.0); }

// A point of the band with its exact u = y - K.
struct Point {
  double y;
  double u;
};

// An interior stationary point y_c = R K / (R - r) of the arc functions (E12), used only if
// R != r, |K| < |R - r| and a < y_c < b. u_c = y_c - K = K r / (R - r).
std::optional<Point> arc_stationary_point(double r, double R, double K, const Band& band) {
  if (R == r || !(std::abs(K) < std::abs(R - r))) {
    return std::nullopt;
  }
  const double yc = R * K / (R - r);
  if (!(band.a < yc && yc < band.b)) {
    return std::nullopt;
  }
  return Point{yc, K * r / (R - r)};
}

}  // namespace

double half_chord(double r, double u) { return root_diff(r, u); }

double cot_deg(double alpha_deg) {
  if (alpha_deg == 90.0) {
    return 0.0;
  }
  return 1.0 / std::tan(radians(alpha_deg));
}

std::optional<Band> steady_band(double r, double K, double lo, double hi) {
  // Normative no-contact test (spec section 8): W = min(K + r, hi) - max(K - r, lo) <= 0.
  const double width = std::min(K + r, hi) - std::max(K - r, lo);
  if (!(width > 0.0)) {
    return std::nullopt;
  }
  Band band;
  band.width = width;
  if (K - r >= lo) {
    band.a = K - r;
    band.ua = -r;
  } else {
    band.a = lo;
    band.ua = lo - K;
  }
  if (K + r <= hi) {
    band.b = K + r;
    band.ub = r;
  } else {
    band.b = hi;
    band.ub = hi - K;
  }
  return band;
}

// ---- 6.1
// -------------------------------------------------------------------------------------------

StraightCase straight90_case(double r, double h, double K) {
  const double k = std::abs(K);
  if (k <= h) {
    return r <= h + k ? StraightCase::S1 : StraightCase::S2;
  }
  return r <= h + k ? StraightCase::S3 : StraightCase::S4;
}

std::optional<EntryForm> straight90_entry(double D, double B, double K, double approach) {
  const double r = D / 2.0;
  const double h = B / 2.0;
  const auto band = steady_band(r, K, -h, h);
  if (!band) {
    return std::nullopt;
  }
  // E13
  const double k = std::abs(K);
  const double d0 = std::max(0.0, k - h);
  const double m = std::min(r, h + k);
  const double first = root_diff(r, d0);  // -x_c0
  const double last = root_diff(r, m);    // -x_cs
  EntryForm form;
  form.engagement_mm = first - last;
  form.start_x_mm = approach + first;
  form.start_y_mm = h + K;
  form.steady_width_mm = band->width;
  form.saturation_x_mm = -last;
  return form;
}

std::optional<ExitForm> straight90_exit(double D, double B, double K) {
  const double r = D / 2.0;
  const double h = B / 2.0;
  if (!steady_band(r, K, -h, h)) {
    return std::nullopt;
  }
  const double m = std::min(r, h + std::abs(K));
  return ExitForm{root_diff(r, m), h + K};  // E13 perpendicular exit
}

// ---- 6.2
// -------------------------------------------------------------------------------------------

std::optional<EntryForm> straight_entry(double D, double B, double K, double alpha_deg,
                                        double approach) {
  const double r = D / 2.0;
  const double h = B / 2.0;
  const auto band = steady_band(r, K, -h, h);
  if (!band) {
    return std::nullopt;
  }
  const double cot = cot_deg(alpha_deg);
  const double cos_alpha = alpha_deg == 90.0 ? 0.0 : std::cos(radians(alpha_deg));
  // E14: g(y) = s(y - K) - (y + h) cot(alpha) = -psi(y)
  const auto g = [&](Point p) { return half_chord(r, p.u) - (p.y + h) * cot; };
  const Point pa{band->a, band->ua};
  const Point pb{band->b, band->ub};
  const double y_free = K - r * cos_alpha;
  Point star{y_free, -r * cos_alpha};
  if (y_free <= band->a) {
    star = pa;
  } else if (y_free >= band->b) {
    star = pb;
  }
  const double g_star = g(star);
  const double g_min = std::min(g(pa), g(pb));
  EntryForm form;
  form.engagement_mm = g_star - g_min;
  form.start_x_mm = approach + g_star;
  form.start_y_mm = h + K;
  form.steady_width_mm = band->width;
  form.saturation_x_mm = -g_min;
  return form;
}

std::optional<EntryForm> straight_entry_band_inside(double D, double B, double K, double alpha_deg,
                                                    double approach) {
  const double r = D / 2.0;
  const double h = B / 2.0;
  if (!(std::abs(K) + r <= h)) {
    return std::nullopt;
  }
  const double a = radians(alpha_deg);
  const double sin_a = std::sin(a);
  const double abs_cos = alpha_deg == 90.0 ? 0.0 : std::abs(std::cos(a));
  const double cot = cot_deg(alpha_deg);
  EntryForm form;
  form.engagement_mm = r * (1.0 + abs_cos) / sin_a;        // E15
  form.start_x_mm = approach + r / sin_a - (h + K) * cot;  // E15
  form.start_y_mm = h + K;
  form.steady_width_mm = 2.0 * r;
  form.saturation_x_mm = form.engagement_mm + approach - form.start_x_mm;
  return form;
}

std::optional<ExitForm> straight_exit(double D, double B, double K, double alpha_x_deg) {
  const double r = D / 2.0;
  const double h = B / 2.0;
  const auto band = steady_band(r, K, -h, h);
  if (!band) {
    return std::nullopt;
  }
  const double cot = cot_deg(alpha_x_deg);
  // E16: phi(y) = (y + h) cot(alpha_x) - s(y - K), convex: its max is at a band end.
  const auto phi = [&](double y, double u) { return (y + h) * cot - half_chord(r, u); };
  const double phi_max = std::max(phi(band->a, band->ua), phi(band->b, band->ub));
  return ExitForm{-phi_max, h + K};
}

std::optional<ExitForm> straight_exit_band_inside(double D, double B, double K,
                                                  double alpha_x_deg) {
  const double r = D / 2.0;
  const double h = B / 2.0;
  if (!(std::abs(K) + r <= h)) {
    return std::nullopt;
  }
  const double cot = cot_deg(alpha_x_deg);
  return ExitForm{-(h + K) * cot - r * std::abs(cot), h + K};  // E16 band inside
}

// ---- 6.3
// -------------------------------------------------------------------------------------------

ConvexCase convex_full_case(double r, double R, double K) {
  const double k = std::abs(K);
  if (r <= R) {
    return k + r <= R ? ConvexCase::A : ConvexCase::B;
  }
  return r <= R + k ? ConvexCase::C : ConvexCase::D;
}

std::optional<EntryForm> convex_full_entry(double D, double R, double K, double approach) {
  const double r = D / 2.0;
  const auto band = steady_band(r, K, -R, R);
  if (!band) {
    return std::nullopt;
  }
  const double k = std::abs(K);
  const double T = root_diff(R + r, k);  // E18
  double Q = 0.0;
  switch (convex_full_case(r, R, K)) {
    case ConvexCase::A:
      Q = root_diff(R, k + r);
      break;
    case ConvexCase::B:
      Q = root_diff(r, k - R);
      break;
    case ConvexCase::C:
      Q = root_diff(R, r - k);
      break;
    case ConvexCase::D:
      Q = root_diff(r, R + k);
      break;
  }
  EntryForm form;
  form.engagement_mm = T - Q;
  form.start_x_mm = approach + T - R;
  form.start_y_mm = K;
  form.steady_width_mm = band->width;
  form.saturation_x_mm = R - Q;  // x_c0 + L_vr1 = (R - T) + (T - Q)
  return form;
}

std::optional<ExitForm> convex_full_exit(double D, double R, double K) {
  const double r = D / 2.0;
  if (!steady_band(r, K, -R, R)) {
    return std::nullopt;
  }
  const double k = std::abs(K);
  // E19 full width
  if (k < r - R) {
    return ExitForm{R + root_diff(r - R, k), K};  // the cutter engulfs the arc
  }
  return ExitForm{R - root_diff(R, r - k), K};
}

std::optional<EntryForm> convex_entry_on(double D, double R, double K, double lo, double hi,
                                         double approach) {
  const double r = D / 2.0;
  const auto band = steady_band(r, K, lo, hi);
  if (!band) {
    return std::nullopt;
  }
  // E17: psi(y) = R - sqrt(R^2 - y^2) - s(y - K), convex.
  const auto psi = [&](Point p) { return R - root_diff(R, p.y) - half_chord(r, p.u); };
  const Point pa{band->a, band->ua};
  const Point pb{band->b, band->ub};
  const double y_free = K * R / (R + r);
  Point star{y_free, -K * r / (R + r)};
  if (y_free <= band->a) {
    star = pa;
  } else if (y_free >= band->b) {
    star = pb;
  }
  const double xc0 = psi(star);
  const double xcs = std::max(psi(pa), psi(pb));
  EntryForm form;
  form.engagement_mm = xcs - xc0;
  form.start_x_mm = approach - xc0;
  form.start_y_mm = K;
  form.steady_width_mm = band->width;
  form.saturation_x_mm = xcs;
  return form;
}

std::optional<ExitForm> convex_exit_on(double D, double R, double K, double lo, double hi) {
  const double r = D / 2.0;
  const auto band = steady_band(r, K, lo, hi);
  if (!band) {
    return std::nullopt;
  }
  // E19: phi(y) = sqrt(R^2 - y^2) - R - s(y - K); X_k = -max phi over {a, b, y_c}.
  const auto phi = [&](Point p) { return root_diff(R, p.y) - R - half_chord(r, p.u); };
  double phi_max = std::max(phi({band->a, band->ua}), phi({band->b, band->ub}));
  if (const auto yc = arc_stationary_point(r, R, K, *band)) {
    phi_max = std::max(phi_max, phi(*yc));
  }
  return ExitForm{-phi_max, K};
}

std::optional<EntryForm> convex_entry(double D, double R, double B, double K, double approach) {
  const double h = std::min(B, 2.0 * R) / 2.0;  // E3
  return convex_entry_on(D, R, K, -h, h, approach);
}

std::optional<ExitForm> convex_exit(double D, double R, double B, double K) {
  const double h = std::min(B, 2.0 * R) / 2.0;  // E3
  return convex_exit_on(D, R, K, -h, h);
}

// ---- 6.4
// -------------------------------------------------------------------------------------------

namespace {

struct ConcaveExtrema {
  double min;
  double max;
  double max_at_ends;
  double width;
  bool has_interior;
};

std::optional<ConcaveExtrema> concave_psi_extrema(double D, double R, double B, double K) {
  const double r = D / 2.0;
  const double h = B / 2.0;
  const auto band = steady_band(r, K, -h, h);
  if (!band) {
    return std::nullopt;
  }
  const double c0 = root_diff(R, h);
  // E20: psi(y) = sqrt(R^2 - y^2) - c0 - s(y - K)
  const auto psi = [&](Point p) { return root_diff(R, p.y) - c0 - half_chord(r, p.u); };
  const double pa = psi({band->a, band->ua});
  const double pb = psi({band->b, band->ub});
  ConcaveExtrema out{std::min(pa, pb), std::max(pa, pb), std::max(pa, pb), band->width, false};
  if (const auto yc = arc_stationary_point(r, R, K, *band)) {
    const double pc = psi(*yc);
    out.min = std::min(out.min, pc);
    out.max = std::max(out.max, pc);
    out.has_interior = true;
  }
  return out;
}

}  // namespace

std::optional<EntryForm> concave_entry(double D, double R, double B, double K, double approach) {
  const auto ext = concave_psi_extrema(D, R, B, K);
  if (!ext) {
    return std::nullopt;
  }
  EntryForm form;
  form.engagement_mm = ext->max - ext->min;
  form.start_x_mm = approach - ext->min;
  form.start_y_mm = K;
  form.steady_width_mm = ext->width;
  form.saturation_x_mm = ext->max;
  return form;
}

bool concave_entry_max_is_interior(double D, double R, double B, double K) {
  const auto ext = concave_psi_extrema(D, R, B, K);
  return ext && ext->has_interior && ext->max > ext->max_at_ends;
}

std::optional<ExitForm> concave_exit(double D, double R, double B, double K) {
  const double r = D / 2.0;
  const double h = B / 2.0;
  const auto band = steady_band(r, K, -h, h);
  if (!band) {
    return std::nullopt;
  }
  const double c0 = root_diff(R, h);
  // E21: phi(y) = c0 - sqrt(R^2 - y^2) - s(y - K), convex: max at a band end.
  const auto phi = [&](double y, double u) { return c0 - root_diff(R, y) - half_chord(r, u); };
  const double phi_max = std::max(phi(band->a, band->ua), phi(band->b, band->ub));
  return ExitForm{-phi_max, K};
}

// ---- 6.5
// -------------------------------------------------------------------------------------------

std::optional<ExitForm> wall_exit(double D, double B, double K) {
  const double r = D / 2.0;
  const double h = B / 2.0;
  if (!steady_band(r, K, -h, h)) {
    return std::nullopt;
  }
  return ExitForm{r, h + K};  // E22
}

}  // namespace cutcalc::test::entry_oracle
