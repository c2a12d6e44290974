// Plan-view scheme of one pass (spec entry-and-main-time.md sections 3-5, E2, E5-E8): the contour
// functions e(y), f(y) and the band S of the existing engine, moved into the workpiece frames.

#include "domain/entry/entry_scheme.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "domain/entry/contour_shape.h"
#include "domain/entry/engagement.h"

namespace cutcalc::domain::entry {

namespace {

enum class Side { entry, exit };

bool is_arc(const Contour& contour) {
  return contour.kind == ContourKind::convex_arc || contour.kind == ContourKind::concave_arc;
}

// Section 3: the lateral positions y (internal frame) at which the contour is drawn, from -h to
// +h. A straight edge or a wall needs its two ends. An arc is sampled uniformly in its angle theta
// (y = R sin theta), so that the steep parts near a half circle's corners get as many points as
// its middle; the ends are exactly -+h and the middle (the apex) exactly 0.
std::vector<double> lateral_samples(const Contour& contour) {
  const double h = detail::half_width_mm(contour);  // h (E3)
  if (!is_arc(contour)) {
    return {-h, h};
  }
  const double R = contour.radius_mm;                             // R
  const double theta_h = std::asin(std::clamp(h / R, 0.0, 1.0));  // half angle over the strip
  constexpr int kSegments = kSchemeArcSegments;                   // even: the apex is a sample
  std::vector<double> samples(static_cast<std::size_t>(kSegments) + 1);
  for (int i = 0; i <= kSegments; ++i) {
    const double theta =
        theta_h * static_cast<double>(2 * i - kSegments) / static_cast<double>(kSegments);  // theta
    samples[static_cast<std::size_t>(i)] = R * std::sin(theta);                             // y
  }
  samples.front() = -h;
  samples.back() = h;
  return samples;
}

// Section 3: X = x_origin - x, the origin being x = 0 of e(y) and f(y). Written as 0 - x so that a
// point on the origin reads +0, never -0.
double frame_x_mm(double x_mm) { return 0.0 - x_mm; }

// The contour e(y) (entry) or f(y) (exit; the face x = 0 for a wall) and the strip, in the frame.
SchemeSide contour_in_frame(const Contour& contour, Side side) {
  SchemeSide out;
  for (const double y : lateral_samples(contour)) {
    const double x = side == Side::entry ? detail::entry_edge_x_mm(contour, y)  // e(y)
                                         : detail::exit_edge_x_mm(contour, y);  // f(y)
    out.contour.push_back(Position{frame_x_mm(x), detail::frame_y_mm(contour, y)});
  }
  const double h = detail::half_width_mm(contour);  // h (E3)
  out.strip = LateralRange{detail::frame_y_mm(contour, -h), detail::frame_y_mm(contour, h)};
  return out;
}

// The workpiece near the contour: the entry region x >= e(y) lies downstream (smaller X), the exit
// region x <= f(y) upstream (larger X). The strip's side edges run `reach_mm` beyond the contour's
// farthest point; at least one ulp, so that the polygon never collapses onto the contour.
void add_workpiece_outline(SchemeSide& out, Side side, double reach_mm) {
  const auto by_x = [](const Position& p, const Position& q) { return p.x_mm < q.x_mm; };
  double far_x = 0.0;
  if (side == Side::entry) {
    const double min_x = std::min_element(out.contour.begin(), out.contour.end(), by_x)->x_mm;
    far_x = min_x - reach_mm;
    if (!(far_x < min_x)) {
      far_x = std::nextafter(min_x, -std::numeric_limits<double>::infinity());
    }
  } else {
    const double max_x = std::max_element(out.contour.begin(), out.contour.end(), by_x)->x_mm;
    far_x = max_x + reach_mm;
    if (!(far_x > max_x)) {
      far_x = std::nextafter(max_x, std::numeric_limits<double>::infinity());
    }
  }
  out.workpiece_outline = out.contour;
  out.workpiece_outline.push_back(Position{far_x, out.strip.y_max_mm});
  out.workpiece_outline.push_back(Position{far_x, out.strip.y_min_mm});
}

// E2: the steady band S = [a, b] of the axis y = K over the whole contour, in frame Y.
std::optional<LateralRange> band_in_frame(const Contour& contour, double offset_mm,
                                          double cutter_radius_mm) {
  const double h = detail::half_width_mm(contour);  // h (E3)
  const std::optional<detail::Band> band =
      detail::steady_band(detail::LateralSetting{offset_mm, cutter_radius_mm, -h, h});
  if (!band) {
    return std::nullopt;
  }
  return LateralRange{detail::frame_y_mm(contour, band->lower.y_mm),
                      detail::frame_y_mm(contour, band->upper.y_mm)};
}

bool finite(const Position& p) { return std::isfinite(p.x_mm) && std::isfinite(p.y_mm); }

bool all_finite(const SchemeSide& side) {
  const auto finite_range = [](const LateralRange& range) {
    return std::isfinite(range.y_min_mm) && std::isfinite(range.y_max_mm);
  };
  bool ok = finite_range(side.strip) && finite_range(side.band);
  for (const Position& p : side.workpiece_outline) {  // holds every contour point
    ok = ok && finite(p);
  }
  for (const SchemePosition& position : side.positions) {
    ok = ok && finite(position.axis);
  }
  return ok;
}

DomainError empty_band(const char* where) {
  std::string detail = "the cutter does not reach the workpiece at the ";
  detail += where;
  return make_error(ErrorCode::no_contact, detail);
}

}  // namespace

// Sections 3-5, E2, E5-E8
Result<EntryScheme> entry_scheme(const EntryLengthParams& params, const EntryLengthResult& result) {
  const double D = params.cutter_diameter_mm;  // D
  const double r = D / 2.0;                    // r (E1)
  const double K = params.offset_mm;           // K
  const double L_vr = result.entry_length_mm;  // L_vr (E6)
  const double reach = std::max(3.0 * D, L_vr + D);

  EntryScheme scheme;
  scheme.cutter_radius_mm = r;

  scheme.entry = contour_in_frame(params.entry, Side::entry);
  const std::optional<LateralRange> entry_band = band_in_frame(params.entry, K, r);
  if (!entry_band) {
    return empty_band("entry");
  }
  scheme.entry.band = *entry_band;
  add_workpiece_outline(scheme.entry, Side::entry, reach);
  const Position start = result.start;  // X_n, Y_n (E7)
  scheme.entry.positions = {
      {SchemePositionKind::start, start},
      {SchemePositionKind::first_contact,
       Position{start.x_mm - params.approach_mm, start.y_mm}},  // X_n - L_pod = -xc0 (E5, E7)
      {SchemePositionKind::saturation,
       Position{start.x_mm - L_vr, start.y_mm}},  // X_n - L_vr = -xcs (E5-E7)
  };
  bool ok = all_finite(scheme.entry);

  if (params.exit && result.exit) {
    // Entry and exit share the symmetry line (section 3): the axis keeps its offset K.
    const Contour& exit_contour = params.exit->contour;
    SchemeSide exit = contour_in_frame(exit_contour, Side::exit);
    const std::optional<LateralRange> exit_band = band_in_frame(exit_contour, K, r);
    if (!exit_band) {
      return empty_band("exit");
    }
    exit.band = *exit_band;
    add_workpiece_outline(exit, Side::exit, reach);
    exit.positions = {{SchemePositionKind::end, result.exit->end}};  // X_k, Y_k (E8)
    ok = ok && all_finite(exit);
    scheme.exit = std::move(exit);
  }

  if (!(ok && std::isfinite(r))) {
    return make_error(ErrorCode::not_converged, "the scheme is too large to represent");
  }
  return scheme;
}

}  // namespace cutcalc::domain::entry
