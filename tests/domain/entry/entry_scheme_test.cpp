// Unit tests: the plan-view scheme of one pass (entry_scheme; spec entry-and-main-time.md sections
// 3-5, E2, E5-E8). The contour oracle here is written from the spec's frame rules directly in
// frame coordinates (X = -x, Y = y + h for straight edges and walls, Y = y for arcs), independently
// of domain/entry/contour_shape.cpp. Every check is geometric: positions against the result, the
// contour on its curve, the disc touching the contour at first contact, clear of it by L_pod at the
// start and covering the exit band at the end, and a simple workpiece polygon.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "domain/entry/entry_length.h"
#include "domain/entry/entry_scheme.h"
#include "domain/entry/entry_test_support.h"

namespace {

using cutcalc::domain::entry::compute_entry_length;
using cutcalc::domain::entry::Contour;
using cutcalc::domain::entry::ContourKind;
using cutcalc::domain::entry::entry_scheme;
using cutcalc::domain::entry::EntryLengthParams;
using cutcalc::domain::entry::EntryLengthResult;
using cutcalc::domain::entry::EntryScheme;
using cutcalc::domain::entry::kSchemeArcSegments;
using cutcalc::domain::entry::part_width_mm;
using cutcalc::domain::entry::Position;
using cutcalc::domain::entry::SchemePositionKind;
using cutcalc::domain::entry::SchemeSide;
using cutcalc::test::concave_contour;
using cutcalc::test::convex_contour;
using cutcalc::test::entry_exit;
using cutcalc::test::entry_only;
using cutcalc::test::outcome;
using cutcalc::test::straight_contour;
using cutcalc::test::wall_contour;

enum class Side { entry, exit };

using cutcalc::test::kTol;
// The dense sweeps below evaluate 200001 lateral positions; a smooth minimum between two of them
// is missed by far less than this.
constexpr double kSweepTol = 1e-6;
constexpr int kSweepSamples = 200000;

bool is_arc(const Contour& c) {
  return c.kind == ContourKind::convex_arc || c.kind == ContourKind::concave_arc;
}

bool is_straight_like(const Contour& c) {
  return c.kind == ContourKind::straight || c.kind == ContourKind::wall;
}

double cot_of(double alpha_deg) {
  return alpha_deg == 90.0 ? 0.0 : 1.0 / std::tan(alpha_deg * std::numbers::pi / 180.0);
}

// Section 3 in frame coordinates: the contour's X at frame Y.
//   straight: X = -e = -(y + h) cot(alpha) = -Y cot(alpha) (entry and exit alike)
//   convex:   entry X = -(R - sqrt(R^2 - Y^2)),  exit X = R - sqrt(R^2 - Y^2)
//   concave:  entry X = -(sqrt(R^2 - Y^2) - c0), exit X = sqrt(R^2 - Y^2) - c0
//   wall:     the face X = 0
double contour_x(const Contour& c, Side side, double Y) {
  const double sign = side == Side::entry ? -1.0 : 1.0;
  const double R = c.radius_mm;
  switch (c.kind) {
    case ContourKind::straight:
      return -Y * cot_of(c.angle_deg);
    case ContourKind::convex_arc:
      return sign * (R - std::sqrt(std::max(0.0, R * R - Y * Y)));
    case ContourKind::concave_arc: {
      const double h = part_width_mm(c) / 2.0;
      const double c0 = std::sqrt(R * R - h * h);
      return sign * (std::sqrt(std::max(0.0, R * R - Y * Y)) - c0);
    }
    case ContourKind::wall:
      return 0.0;
  }
  return 0.0;
}

// The arc's centre in frame coordinates (on Y = 0): convex entry (-R, 0), convex exit (R, 0),
// concave entry (c0, 0), concave exit (-c0, 0).
double arc_centre_x(const Contour& c, Side side) {
  const double sign = side == Side::entry ? -1.0 : 1.0;
  if (c.kind == ContourKind::convex_arc) {
    return sign * c.radius_mm;
  }
  const double h = part_width_mm(c) / 2.0;
  return -sign * std::sqrt(c.radius_mm * c.radius_mm - h * h);
}

// Section 3: Y of the internal lateral y.
double frame_y(const Contour& c, double y) {
  return is_straight_like(c) ? y + part_width_mm(c) / 2.0 : y;
}

double half_chord(double r, double u) { return std::sqrt(std::max(0.0, r * r - u * u)); }

double distance_to_segment(const Position& p, const Position& a, const Position& b) {
  const double dx = b.x_mm - a.x_mm;
  const double dy = b.y_mm - a.y_mm;
  const double length_sq = dx * dx + dy * dy;
  double t = length_sq > 0.0 ? ((p.x_mm - a.x_mm) * dx + (p.y_mm - a.y_mm) * dy) / length_sq : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x_mm - (a.x_mm + t * dx), p.y_mm - (a.y_mm + t * dy));
}

double distance_to_polyline(const Position& p, const std::vector<Position>& line) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    best = std::min(best, distance_to_segment(p, line[i], line[i + 1]));
  }
  return best;
}

// The largest gap between an arc and its polyline: R (1 - cos(dtheta / 2)) for the uniform angle
// step dtheta over the strip; 0 for a straight edge.
double sampling_error(const Contour& c) {
  if (!is_arc(c)) {
    return 0.0;
  }
  const double R = c.radius_mm;
  const double theta_h = std::asin(std::min(1.0, part_width_mm(c) / 2.0 / R));
  const double step = 2.0 * theta_h / kSchemeArcSegments;
  return R * (1.0 - std::cos(step / 2.0));
}

double cross(const Position& o, const Position& a, const Position& b) {
  return (a.x_mm - o.x_mm) * (b.y_mm - o.y_mm) - (a.y_mm - o.y_mm) * (b.x_mm - o.x_mm);
}

bool on_segment(const Position& p, const Position& a, const Position& b) {
  return std::min(a.x_mm, b.x_mm) <= p.x_mm && p.x_mm <= std::max(a.x_mm, b.x_mm) &&
         std::min(a.y_mm, b.y_mm) <= p.y_mm && p.y_mm <= std::max(a.y_mm, b.y_mm);
}

// Closed segments [a, b] and [c, d] share a point (touching and collinear overlap included).
bool segments_meet(const Position& a, const Position& b, const Position& c, const Position& d) {
  const double d1 = cross(c, d, a);
  const double d2 = cross(c, d, b);
  const double d3 = cross(a, b, c);
  const double d4 = cross(a, b, d);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) {
    return true;
  }
  return (d1 == 0 && on_segment(a, c, d)) || (d2 == 0 && on_segment(b, c, d)) ||
         (d3 == 0 && on_segment(c, a, b)) || (d4 == 0 && on_segment(d, a, b));
}

// The polygon (closed implicitly) has no two non-adjacent edges that meet and a non-zero area.
void expect_simple_polygon(const std::vector<Position>& polygon, const std::string& what) {
  const std::size_t n = polygon.size();
  ASSERT_GE(n, 3U) << what;
  EXPECT_FALSE(polygon.front().x_mm == polygon.back().x_mm &&
               polygon.front().y_mm == polygon.back().y_mm)
      << what << ": the last point repeats the first";
  double twice_area = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Position& p = polygon[i];
    const Position& q = polygon[(i + 1) % n];
    twice_area += p.x_mm * q.y_mm - q.x_mm * p.y_mm;
  }
  EXPECT_GT(std::abs(twice_area), 0.0) << what;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) {
        continue;  // the closing edge is adjacent to the first
      }
      ASSERT_FALSE(
          segments_meet(polygon[i], polygon[(i + 1) % n], polygon[j], polygon[(j + 1) % n]))
          << what << ": edges " << i << " and " << j << " meet";
    }
  }
}

struct Solved {
  EntryLengthResult result;
  EntryScheme scheme;
};

Solved solve(const EntryLengthParams& params) {
  const auto result = compute_entry_length(params);
  EXPECT_TRUE(result.ok()) << outcome(result);
  if (!result.ok()) {
    return {};
  }
  const auto scheme = entry_scheme(params, result.value());
  EXPECT_TRUE(scheme.ok()) << outcome(scheme);
  if (!scheme.ok()) {
    return {};
  }
  return {result.value(), scheme.value()};
}

// What every side shares: the contour on its curve (section 3), the strip, the band (E2) and the
// workpiece outline reaching `reach` beyond the contour.
void expect_side_geometry(const SchemeSide& side, const Contour& c, Side which, double r, double K,
                          double reach) {
  const double B = part_width_mm(c);
  const double h = B / 2.0;
  EXPECT_NEAR(side.strip.y_min_mm, frame_y(c, -h), kTol);
  EXPECT_NEAR(side.strip.y_max_mm, frame_y(c, h), kTol);
  EXPECT_NEAR(side.band.y_min_mm, frame_y(c, std::max(K - r, -h)), kTol);  // a (E2)
  EXPECT_NEAR(side.band.y_max_mm, frame_y(c, std::min(K + r, h)), kTol);   // b (E2)

  const std::vector<Position>& contour = side.contour;
  ASSERT_EQ(contour.size(), is_arc(c) ? static_cast<std::size_t>(kSchemeArcSegments) + 1 : 2U);
  EXPECT_NEAR(contour.front().y_mm, side.strip.y_min_mm, kTol);
  EXPECT_NEAR(contour.back().y_mm, side.strip.y_max_mm, kTol);
  const double scale = std::max({1.0, B, c.radius_mm});
  for (std::size_t i = 0; i < contour.size(); ++i) {
    const Position& p = contour[i];
    if (i > 0) {
      EXPECT_GT(p.y_mm, contour[i - 1].y_mm) << "contour Y must increase, point " << i;
    }
    if (is_arc(c)) {
      const double centre = arc_centre_x(c, which);
      EXPECT_NEAR(std::hypot(p.x_mm - centre, p.y_mm), c.radius_mm, kTol * scale) << i;
      // The near half of the circle: an entry contour lies at X <= 0, an exit one at X >= 0.
      EXPECT_LE(which == Side::entry ? p.x_mm : -p.x_mm, kTol * scale) << i;
    } else {
      EXPECT_NEAR(p.x_mm, contour_x(c, which, p.y_mm), kTol * scale) << i;
    }
  }

  // The outline: the contour, then the strip's two far corners.
  const std::vector<Position>& outline = side.workpiece_outline;
  ASSERT_EQ(outline.size(), contour.size() + 2);
  for (std::size_t i = 0; i < contour.size(); ++i) {
    EXPECT_EQ(outline[i].x_mm, contour[i].x_mm) << i;
    EXPECT_EQ(outline[i].y_mm, contour[i].y_mm) << i;
  }
  const auto by_x = [](const Position& p, const Position& q) { return p.x_mm < q.x_mm; };
  const double far_x = which == Side::entry
                           ? std::min_element(contour.begin(), contour.end(), by_x)->x_mm - reach
                           : std::max_element(contour.begin(), contour.end(), by_x)->x_mm + reach;
  const Position& corner_1 = outline[contour.size()];
  const Position& corner_2 = outline[contour.size() + 1];
  EXPECT_NEAR(corner_1.x_mm, far_x, kTol * scale);
  EXPECT_NEAR(corner_1.y_mm, side.strip.y_max_mm, kTol);
  EXPECT_NEAR(corner_2.x_mm, far_x, kTol * scale);
  EXPECT_NEAR(corner_2.y_mm, side.strip.y_min_mm, kTol);
  expect_simple_polygon(outline, which == Side::entry ? "entry outline" : "exit outline");
}

// The entry side: positions (E5-E7), the disc touching the contour at first contact and clear of
// it by L_pod along X at the start.
void expect_entry_scheme(const EntryLengthParams& params, const Solved& solved) {
  const EntryScheme& scheme = solved.scheme;
  const EntryLengthResult& result = solved.result;
  const double r = params.cutter_diameter_mm / 2.0;
  const double K = params.offset_mm;
  const double reach =
      std::max(3.0 * params.cutter_diameter_mm, result.entry_length_mm + params.cutter_diameter_mm);
  EXPECT_NEAR(scheme.cutter_radius_mm, r, kTol);
  {
    SCOPED_TRACE("entry side");
    expect_side_geometry(scheme.entry, params.entry, Side::entry, r, K, reach);
  }

  const auto& positions = scheme.entry.positions;
  ASSERT_EQ(positions.size(), 3U);
  EXPECT_EQ(positions[0].kind, SchemePositionKind::start);
  EXPECT_EQ(positions[1].kind, SchemePositionKind::first_contact);
  EXPECT_EQ(positions[2].kind, SchemePositionKind::saturation);
  const Position start = positions[0].axis;
  const Position first = positions[1].axis;
  const Position saturation = positions[2].axis;
  EXPECT_NEAR(start.x_mm, result.start.x_mm, kTol);  // X_n
  EXPECT_NEAR(start.y_mm, result.start.y_mm, kTol);  // Y_n
  EXPECT_NEAR(start.y_mm, frame_y(params.entry, K), kTol);
  EXPECT_NEAR(first.x_mm, result.start.x_mm - params.approach_mm, kTol);
  EXPECT_NEAR(saturation.x_mm, result.start.x_mm - result.entry_length_mm, kTol);
  EXPECT_NEAR(first.x_mm - saturation.x_mm, result.engagement_length_mm, kTol * 100);  // L_vr1
  EXPECT_EQ(first.y_mm, start.y_mm);
  EXPECT_EQ(saturation.y_mm, start.y_mm);

  // First contact: the disc touches the contour (E5); only the polyline's chords separate the two.
  const double touch_tol = sampling_error(params.entry) + kTol * std::max(1.0, r);
  EXPECT_NEAR(distance_to_polyline(first, scheme.entry.contour), r, touch_tol);
  // At the start it does not reach it.
  EXPECT_GE(distance_to_polyline(start, scheme.entry.contour), r - touch_tol);

  // Along X, over the band: the disc's downstream edge at the start is X_n - s(Y - Y_n); the gap to
  // the contour is never below L_pod and is L_pod where first contact happens (E10).
  const double y_low = scheme.entry.band.y_min_mm;
  const double y_high = scheme.entry.band.y_max_mm;
  double least_gap = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= kSweepSamples; ++i) {
    const double Y = y_low + (y_high - y_low) * i / kSweepSamples;
    const double gap =
        start.x_mm - half_chord(r, Y - start.y_mm) - contour_x(params.entry, Side::entry, Y);
    least_gap = std::min(least_gap, gap);
  }
  EXPECT_GE(least_gap, params.approach_mm - kSweepTol);
  EXPECT_NEAR(least_gap, params.approach_mm, kSweepTol);

  // Saturation: the disc at X_n - L_vr has reached the contour over the whole band (E5), and not
  // earlier: (X - s(Y - Y_n)) - X_c(Y) is <= 0 everywhere and 0 somewhere.
  double largest_gap = -std::numeric_limits<double>::infinity();
  for (int i = 0; i <= kSweepSamples; ++i) {
    const double Y = y_low + (y_high - y_low) * i / kSweepSamples;
    const double gap =
        saturation.x_mm - half_chord(r, Y - start.y_mm) - contour_x(params.entry, Side::entry, Y);
    largest_gap = std::max(largest_gap, gap);
  }
  EXPECT_NEAR(largest_gap, 0.0, kSweepTol);
}

// The exit side: the end position (E8) and the disc covering the band there.
void expect_exit_scheme(const EntryLengthParams& params, const Solved& solved) {
  ASSERT_TRUE(params.exit.has_value());
  ASSERT_TRUE(solved.result.exit.has_value());
  ASSERT_TRUE(solved.scheme.exit.has_value());
  const SchemeSide& side = *solved.scheme.exit;
  const Contour& c = params.exit->contour;
  const double r = params.cutter_diameter_mm / 2.0;
  const double K = params.offset_mm;
  const double reach = std::max(3.0 * params.cutter_diameter_mm,
                                solved.result.entry_length_mm + params.cutter_diameter_mm);
  {
    SCOPED_TRACE("exit side");
    expect_side_geometry(side, c, Side::exit, r, K, reach);
  }
  ASSERT_EQ(side.positions.size(), 1U);
  EXPECT_EQ(side.positions[0].kind, SchemePositionKind::end);
  const Position end = side.positions[0].axis;
  EXPECT_NEAR(end.x_mm, solved.result.exit->end.x_mm, kTol);  // X_k
  EXPECT_NEAR(end.y_mm, solved.result.exit->end.y_mm, kTol);  // Y_k
  EXPECT_NEAR(end.y_mm, frame_y(c, K), kTol);

  if (c.kind == ContourKind::wall) {
    // E22: the periphery stops at the face.
    EXPECT_NEAR(distance_to_polyline(end, side.contour), r, kTol);
    return;
  }
  // E8 in the exit frame: the disc's downstream edge X_k - s(Y - Y_k) is at or beyond the contour
  // over the whole band, and exactly on it somewhere.
  double least = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= kSweepSamples; ++i) {
    const double Y =
        side.band.y_min_mm + (side.band.y_max_mm - side.band.y_min_mm) * i / kSweepSamples;
    least = std::min(least, contour_x(c, Side::exit, Y) - (end.x_mm - half_chord(r, Y - end.y_mm)));
  }
  EXPECT_NEAR(least, 0.0, kSweepTol);
}

void expect_scheme(const EntryLengthParams& params) {
  const auto result = compute_entry_length(params);
  ASSERT_TRUE(result.ok()) << outcome(result);
  const auto scheme = entry_scheme(params, result.value());
  ASSERT_TRUE(scheme.ok()) << outcome(scheme);
  const Solved solved{result.value(), scheme.value()};
  expect_entry_scheme(params, solved);
  if (params.exit) {
    expect_exit_scheme(params, solved);
  } else {
    EXPECT_FALSE(solved.scheme.exit.has_value());
  }
}

}  // namespace

TEST(EntryScheme, StraightPerpendicularEdges) {
  // S1 at both ends: D = 20 inside B = 40.
  const auto params = entry_exit(20.0, 0.0, straight_contour(40.0), straight_contour(40.0), 100.0);
  expect_scheme(params);
  const Solved solved = solve(params);
  // alpha = 90: the contour is the whole edge at X = 0, strip and band in Y from the side edge.
  ASSERT_EQ(solved.scheme.entry.contour.size(), 2U);
  EXPECT_EQ(solved.scheme.entry.contour[0].x_mm, 0.0);
  EXPECT_FALSE(std::signbit(solved.scheme.entry.contour[0].x_mm)) << "no -0 in a response";
  EXPECT_EQ(solved.scheme.entry.contour[1].y_mm, 40.0);
  EXPECT_NEAR(solved.scheme.entry.band.y_min_mm, 10.0, kTol);
  EXPECT_NEAR(solved.scheme.entry.band.y_max_mm, 30.0, kTol);
  // The cutter reaches 3 D = 60 beyond the edge: X = -60.
  EXPECT_NEAR(solved.scheme.entry.workpiece_outline[2].x_mm, -60.0, kTol);
  EXPECT_NEAR(solved.scheme.exit->workpiece_outline[2].x_mm, 60.0, kTol);
}

TEST(EntryScheme, StraightPerpendicularCutterWiderThanStripWithOffset) {
  // S4: |K| > h and r > h + |K| (H08 kind), both signs of K.
  expect_scheme(entry_exit(60.0, 15.0, straight_contour(20.0), straight_contour(20.0), 100.0));
  expect_scheme(entry_exit(60.0, -15.0, straight_contour(20.0), straight_contour(20.0), 100.0));
  // S3: the axis outside the strip, the band clipped by the cutter's edge.
  expect_scheme(entry_only(20.0, 25.0, straight_contour(40.0)));
}

TEST(EntryScheme, InclinedEdgeBelowNinetyDegrees) {
  // Section 11: alpha = 60, B = 40, D = 30: L_vr1 = 11.914 for K = +10 and 25.981 for K = -10.
  const auto plus =
      entry_exit(30.0, 10.0, straight_contour(40.0, 60.0), straight_contour(40.0, 60.0), 200.0);
  const auto minus =
      entry_exit(30.0, -10.0, straight_contour(40.0, 60.0), straight_contour(40.0, 60.0), 200.0);
  expect_scheme(plus);
  expect_scheme(minus);
  const Solved p = solve(plus);
  const Solved m = solve(minus);
  EXPECT_NEAR(p.scheme.entry.positions[1].axis.x_mm - p.scheme.entry.positions[2].axis.x_mm, 11.914,
              1e-3);
  EXPECT_NEAR(m.scheme.entry.positions[1].axis.x_mm - m.scheme.entry.positions[2].axis.x_mm, 25.981,
              1e-3);
  // The edge runs from the origin corner (0, 0) to (-B cot(alpha), B).
  EXPECT_NEAR(p.scheme.entry.contour[1].x_mm, -40.0 / std::sqrt(3.0), 1e-12);
}

TEST(EntryScheme, InclinedEdgeAboveNinetyDegrees) {
  // alpha > 90: the origin corner trails; the far corner is upstream (X > 0).
  const auto params =
      entry_exit(20.0, 5.0, straight_contour(40.0, 120.0), straight_contour(40.0, 110.0), 150.0);
  expect_scheme(params);
  const Solved solved = solve(params);
  EXPECT_GT(solved.scheme.entry.contour[1].x_mm, 0.0);
  // A small angle with a wide strip: the corner leads far upstream and X_n < 0 (H11 kind).
  expect_scheme(entry_only(20.0, 0.0, straight_contour(100.0, 20.0)));
}

TEST(EntryScheme, ConvexArc) {
  // E18 case A at both ends (T2 row 3).
  expect_scheme(entry_exit(20.0, 15.0, convex_contour(50.0), convex_contour(50.0), 200.0));
  // A partial arc (H31 kind) and a cutter that engulfs it (case D, r > R + |K|).
  expect_scheme(
      entry_exit(20.0, -8.0, convex_contour(50.0, 60.0), convex_contour(50.0, 60.0), 200.0));
  expect_scheme(entry_exit(80.0, 5.0, convex_contour(20.0), convex_contour(20.0), 200.0));
  // K^2 > r^2 + 2 R r: first contact lies downstream of the apex (E18), X_n < L_pod.
  const auto params = entry_only(10.0, 35.0, convex_contour(40.0));
  expect_scheme(params);
  const Solved solved = solve(params);
  EXPECT_LT(solved.scheme.entry.positions[0].axis.x_mm, 2.0);
  // The apex (the middle sample) is the origin.
  const Position apex = solved.scheme.entry.contour[kSchemeArcSegments / 2];
  EXPECT_EQ(apex.x_mm, 0.0);
  EXPECT_EQ(apex.y_mm, 0.0);
}

TEST(EntryScheme, ConcaveArc) {
  expect_scheme(
      entry_exit(16.0, 4.0, concave_contour(30.0, 40.0), concave_contour(30.0, 40.0), 150.0));
  // r > R: the maximum of psi at the interior tangency y_c (HX02 kind).
  expect_scheme(entry_only(80.0, 3.0, concave_contour(30.0, 50.0)));
  // A half-circle notch (B = 2R): the contour starts and ends on the X = 0 line at Y = -+R.
  const auto params =
      entry_exit(10.0, -6.0, concave_contour(20.0, 40.0), concave_contour(20.0, 40.0), 150.0);
  expect_scheme(params);
  const Solved solved = solve(params);
  EXPECT_EQ(solved.scheme.entry.contour.front().x_mm, 0.0);
  EXPECT_EQ(solved.scheme.entry.contour.back().x_mm, 0.0);
  EXPECT_NEAR(solved.scheme.entry.contour[kSchemeArcSegments / 2].x_mm, -20.0, kTol);
}

TEST(EntryScheme, WallExit) {
  const auto params = entry_exit(20.0, 5.0, straight_contour(40.0), wall_contour(40.0), 120.0);
  expect_scheme(params);
  const Solved solved = solve(params);
  // The contour is the wall face X = 0 across the strip; the workpiece runs upstream of it.
  const SchemeSide& exit = *solved.scheme.exit;
  ASSERT_EQ(exit.contour.size(), 2U);
  EXPECT_EQ(exit.contour[0].x_mm, 0.0);
  EXPECT_EQ(exit.contour[1].x_mm, 0.0);
  EXPECT_NEAR(exit.positions[0].axis.x_mm, 10.0, kTol);  // X_k = r (E22)
  EXPECT_GT(exit.workpiece_outline.back().x_mm, 0.0);
}

TEST(EntryScheme, MixedContoursWithOffset) {
  // Convex entry, concave exit and the reverse, off-centre.
  expect_scheme(
      entry_exit(24.0, 7.0, convex_contour(30.0, 50.0), concave_contour(40.0, 50.0), 150.0));
  expect_scheme(
      entry_exit(24.0, -7.0, concave_contour(40.0, 50.0), convex_contour(30.0, 50.0), 150.0));
  expect_scheme(entry_exit(12.0, 9.0, straight_contour(30.0, 75.0), convex_contour(15.0), 150.0));
}

TEST(EntryScheme, ApproachOnlyShiftsTheStart) {
  const auto near = solve(entry_only(20.0, 3.0, convex_contour(50.0), 0.0));
  const auto far = solve(entry_only(20.0, 3.0, convex_contour(50.0), 7.5));
  EXPECT_NEAR(far.scheme.entry.positions[0].axis.x_mm - near.scheme.entry.positions[0].axis.x_mm,
              7.5, kTol);
  EXPECT_NEAR(far.scheme.entry.positions[1].axis.x_mm, near.scheme.entry.positions[1].axis.x_mm,
              kTol);
  EXPECT_NEAR(far.scheme.entry.positions[2].axis.x_mm, near.scheme.entry.positions[2].axis.x_mm,
              kTol);
}

TEST(EntryScheme, ExtremeInputsStayFinite) {
  // A nearly flat edge on the widest strip, a tiny cutter on a huge arc and a huge cutter on a
  // tiny notch: every coordinate finite and the outline still a simple polygon.
  const std::vector<EntryLengthParams> cases = {
      entry_only(1e-6, 0.0, straight_contour(1e6, 0.001)),
      entry_only(1e6, 0.0, straight_contour(1e-6, 179.999)),
      entry_exit(1e-3, 0.0, convex_contour(1e6), convex_contour(1e6), 1e6),
      entry_exit(1e6, 1e5, concave_contour(1e-3, 2e-3), concave_contour(1e-3, 2e-3), 1e6),
  };
  for (const auto& params : cases) {
    const Solved solved = solve(params);
    ASSERT_FALSE(::testing::Test::HasFailure());
    const auto check = [](const SchemeSide& side) {
      for (const Position& p : side.workpiece_outline) {
        EXPECT_TRUE(std::isfinite(p.x_mm) && std::isfinite(p.y_mm));
      }
      for (const auto& position : side.positions) {
        EXPECT_TRUE(std::isfinite(position.axis.x_mm) && std::isfinite(position.axis.y_mm));
      }
      expect_simple_polygon(side.workpiece_outline, "outline");
    };
    check(solved.scheme.entry);
    if (solved.scheme.exit) {
      check(*solved.scheme.exit);
    }
  }
}
