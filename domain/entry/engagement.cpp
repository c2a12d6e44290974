// E2 and E10-E12 of spec entry-and-main-time.md: psi and phi evaluated at the band ends and at the
// contour's stationary point, with the numerics rules of sections 5 and 8.

#include "domain/entry/engagement.h"

#include <algorithm>
#include <cmath>

#include "domain/common/numeric.h"
#include "domain/entry/contour_shape.h"

namespace cutcalc::domain::entry::detail {

namespace {

struct Extremes {
  double min = 0.0;
  double max = 0.0;
};

// A band end on the cutter's own edge: u = +-r exactly, so the chord has zero length (tangency).
BandPoint cutter_edge(double y_mm, double u_mm) { return BandPoint{y_mm, u_mm, 0.0}; }

// A band end on the workpiece's edge: y is exact, u = y - K is one rounding away from exact.
BandPoint workpiece_edge(double y_mm, double axis_y_mm, double cutter_radius_mm) {
  const double u = y_mm - axis_y_mm;  // u
  return BandPoint{y_mm, u, sqrt_diff_sq(cutter_radius_mm, u)};
}

// Strictly inside (a, b): a stationary point on an end is already evaluated there, with its exact
// u.
bool inside(const Band& band, double u_mm) {
  return band.lower.u_mm < u_mm && u_mm < band.upper.u_mm;
}

// E10: psi(y) = e(y) - s(y - K)
double psi_mm(const Contour& contour, const BandPoint& point) {
  return entry_edge_x_mm(contour, point.y_mm) - point.half_chord_mm;
}

// E11: phi(y) = f(y) - s(y - K)
double phi_mm(const Contour& contour, const BandPoint& point) {
  return exit_edge_x_mm(contour, point.y_mm) - point.half_chord_mm;
}

// E12 y_c = R K / (R - r): where the disc is tangent, from inside, to the circle of the concave
// entry arc or the convex exit arc. Its value there is sign(R - r) M - c with
// M = sqrt((R - r)^2 - K^2): the roots sqrt(R^2 - y_c^2) = R M/|R - r| and s = r M/|R - r|
// combine exactly, which keeps the digits that evaluating at a rounded y_c would lose.
// Returns nothing when y_c does not exist or is not strictly inside the band.
std::optional<double> inner_tangency_value(double radius_mm, const LateralSetting& setting,
                                           const Band& band, double centre_offset_mm) {
  const double R = radius_mm;                 // R
  const double r = setting.cutter_radius_mm;  // r
  const double K = setting.axis_y_mm;         // K
  if (R == r || !(std::abs(K) < std::abs(R - r))) {
    return std::nullopt;
  }
  const double u_c = K * r / (R - r);  // y_c - K, without subtracting K from a rounded y_c
  if (!inside(band, u_c)) {
    return std::nullopt;
  }
  const double M = sqrt_diff_sq(R - r, K);  // M
  return (R > r ? M : -M) - centre_offset_mm;
}

// E12 straight: psi is convex with its minimum at y* = K - r cos(alpha), where s = r sin(alpha);
// psi(y*) = (h + K) cot(alpha) - r / sin(alpha) (E15).
void straight_entry_stationary(const Contour& contour, const LateralSetting& setting,
                               const Band& band, Extremes& psi) {
  const EdgeTrig trig = edge_trig(contour.angle_deg);
  const double r = setting.cutter_radius_mm;  // r
  const double u_star = -r * trig.cos_alpha;  // y* - K
  if (inside(band, u_star)) {
    const double h = half_width_mm(contour);  // h
    const double value = (h + setting.axis_y_mm) * trig.cot_alpha - r / trig.sin_alpha;
    psi.min = std::min(psi.min, value);
  }
}

// E12 convex arc: psi is convex with its minimum at y* = K R / (R + r), where disc and arc touch
// from outside: psi(y*) = R - sqrt((R + r)^2 - K^2) (E17/E18, T).
void convex_entry_stationary(const Contour& contour, const LateralSetting& setting,
                             const Band& band, Extremes& psi) {
  const double R = contour.radius_mm;         // R
  const double r = setting.cutter_radius_mm;  // r
  const double K = setting.axis_y_mm;         // K
  const double u_star = -K * r / (R + r);     // y* - K
  if (inside(band, u_star)) {
    const double T = sqrt_diff_sq(R + r, K);  // T
    psi.min = std::min(psi.min, R - T);
  }
}

}  // namespace

// E2
std::optional<Band> steady_band(const LateralSetting& setting) {
  const double K = setting.axis_y_mm;         // K
  const double r = setting.cutter_radius_mm;  // r
  const double low_reach = K - r;
  const double high_reach = K + r;
  const double a = std::max(low_reach, setting.lower_edge_mm);   // a
  const double b = std::min(high_reach, setting.upper_edge_mm);  // b
  const double W = b - a;                                        // W
  if (!(W > 0.0)) {
    return std::nullopt;
  }
  Band band;
  band.lower = low_reach >= setting.lower_edge_mm ? cutter_edge(low_reach, -r)
                                                  : workpiece_edge(setting.lower_edge_mm, K, r);
  band.upper = high_reach <= setting.upper_edge_mm ? cutter_edge(high_reach, r)
                                                   : workpiece_edge(setting.upper_edge_mm, K, r);
  band.width_mm = W;
  return band;
}

// E10, E12
EntryExtremes entry_extremes(const Contour& contour, const LateralSetting& setting,
                             const Band& band) {
  const double at_a = psi_mm(contour, band.lower);
  const double at_b = psi_mm(contour, band.upper);
  Extremes psi{std::min(at_a, at_b), std::max(at_a, at_b)};
  switch (contour.kind) {
    case ContourKind::straight:
      straight_entry_stationary(contour, setting, band, psi);
      break;
    case ContourKind::convex_arc:
      convex_entry_stationary(contour, setting, band, psi);
      break;
    case ContourKind::concave_arc: {
      // E20: psi is neither convex nor concave, so y_c is a candidate for both extremes.
      const double c0 = sqrt_diff_sq(contour.radius_mm, half_width_mm(contour));  // c0
      if (const auto value = inner_tangency_value(contour.radius_mm, setting, band, c0)) {
        psi.min = std::min(psi.min, *value);
        psi.max = std::max(psi.max, *value);
      }
      break;
    }
    case ContourKind::wall: {
      // Read as a perpendicular edge (see entry_edge_x_mm): its minimum is where the chord is r.
      const Contour perpendicular{ContourKind::straight, contour.width_mm, 0.0, 90.0};
      straight_entry_stationary(perpendicular, setting, band, psi);
      break;
    }
  }
  return EntryExtremes{psi.min, psi.max};
}

// E11, E12
double exit_end_x_mm(const Contour& contour, const LateralSetting& setting, const Band& band) {
  double x_end = std::max(phi_mm(contour, band.lower), phi_mm(contour, band.upper));  // max phi
  if (contour.kind == ContourKind::convex_arc) {
    // E19: phi is not convex; the disc touching the arc's circle from inside is a candidate.
    if (const auto value =
            inner_tangency_value(contour.radius_mm, setting, band, contour.radius_mm)) {
      x_end = std::max(x_end, *value);
    }
  }
  // Straight and concave exits (E16, E21): phi is convex, its maximum is at an end.
  return x_end;
}

}  // namespace cutcalc::domain::entry::detail
