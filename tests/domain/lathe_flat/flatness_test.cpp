// The flatness error of N steps (lathe-flat.md section 4, F10-F16) against computations of the
// test's own: the point tool's maximum as the root of F11 per segment (bisection), the end mill's
// as the brute-force envelope of the tool circles; never a gouge; the estimate over-estimates; the
// smallest N for a tolerance, in the scanned range and in the bisected one.

#include "domain/lathe_flat/flatness.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <vector>

#include "domain/lathe_flat/lathe_flat_settings.h"

namespace cutcalc::domain::lathe_flat {
namespace {

using settings::kPaper;
using settings::kPaperR5;

double width_of(const FlatSection& flat) {
  return 2.0 * std::sqrt(flat.part_radius_mm * flat.part_radius_mm -
                         flat.axis_distance_mm * flat.axis_distance_mm);
}

double error_of(const FlatSection& flat, int steps) {
  return flatness_error_mm(flat, width_of(flat), steps);
}

// The step point i (F5, F6) from the closed forms, independent of flat_geometry.
struct StepPoint {
  double alpha;
  double x;
};
StepPoint step_point(const FlatSection& flat, int steps, int i) {
  const double alpha_e = std::acos(flat.axis_distance_mm / flat.part_radius_mm);
  const double alpha = alpha_e * (steps - i) / steps;
  return {alpha, (flat.axis_distance_mm + flat.tool_radius_mm) / std::cos(alpha)};
}

// F11 for a point tool: in each first-half segment e(a) = r_lin(a) cos a - d is concave with one
// maximum where e'(a) = k cos a - r_lin(a) sin a = 0; found by bisection, capped by F13.
double point_tool_error_by_root(const FlatSection& flat, int steps) {
  const double r2 = flat.part_radius_mm;
  const double d = flat.axis_distance_mm;
  double worst = 0.0;
  for (int i = 0; i < steps; ++i) {
    const StepPoint p0 = step_point(flat, steps, i);
    const StepPoint p1 = step_point(flat, steps, i + 1);
    const double k = (p1.x - p0.x) / (p1.alpha - p0.alpha);
    const auto r_lin = [&](double a) { return p0.x + (a - p0.alpha) * k; };
    const auto slope = [&](double a) { return k * std::cos(a) - r_lin(a) * std::sin(a); };
    double low = p1.alpha;   // e' > 0
    double high = p0.alpha;  // e' < 0
    for (int step = 0; step < 200 && high - low > 1e-16; ++step) {
      const double middle = 0.5 * (low + high);
      (slope(middle) > 0.0 ? low : high) = middle;
    }
    const double a = 0.5 * (low + high);
    const double u = r_lin(a) * std::sin(a);
    const double e = r_lin(a) * std::cos(a) - d;
    worst = std::max(worst, std::min(e, std::sqrt(r2 * r2 - u * u) - d));
  }
  return worst;
}

// The golden-section maximum of f on [a, b] (the test's own, to 1e-13).
double maximise(const std::function<double(double)>& f, double a, double b) {
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  double c = b - g * (b - a);
  double e = a + g * (b - a);
  double fc = f(c);
  double fe = f(e);
  while (b - a > 1e-13) {
    if (fc > fe) {
      b = e;
      e = c;
      fe = fc;
      c = b - g * (b - a);
      fc = f(c);
    } else {
      a = c;
      c = e;
      fc = fe;
      e = a + g * (b - a);
      fe = f(e);
    }
  }
  return std::max(fc, fe);
}

// The tool centre's path c(s) over the whole flat (2N segments, X and alpha linear in s).
struct Path {
  std::vector<StepPoint> points;
  double centre_x(int seg, double s) const {
    const StepPoint& p = points[static_cast<std::size_t>(seg)];
    const StepPoint& q = points[static_cast<std::size_t>(seg) + 1];
    const double r = p.x + s * (q.x - p.x);
    return r * std::cos(p.alpha + s * (q.alpha - p.alpha));
  }
  double centre_y(int seg, double s) const {
    const StepPoint& p = points[static_cast<std::size_t>(seg)];
    const StepPoint& q = points[static_cast<std::size_t>(seg) + 1];
    const double r = p.x + s * (q.x - p.x);
    return -r * std::sin(p.alpha + s * (q.alpha - p.alpha));
  }
};

// The machined surface at lateral position u: the lowest point of every tool circle that
// crosses the line y = u (the envelope, brute force: dense samples, then refined), minus d.
double envelope_height(const FlatSection& flat, const Path& path, double u) {
  const double r = flat.tool_radius_mm;
  const auto bottom = [&](int seg, double s) {
    const double dy = u - path.centre_y(seg, s);
    if (std::fabs(dy) > r) return std::numeric_limits<double>::infinity();
    return path.centre_x(seg, s) - std::sqrt((r - dy) * (r + dy));
  };
  constexpr int kSamples = 200;
  double lowest = std::numeric_limits<double>::infinity();
  const int segments = static_cast<int>(path.points.size()) - 1;
  for (int seg = 0; seg < segments; ++seg) {
    int best = -1;
    double best_value = std::numeric_limits<double>::infinity();
    for (int k = 0; k <= kSamples; ++k) {
      const double value = bottom(seg, static_cast<double>(k) / kSamples);
      if (value < best_value) {
        best_value = value;
        best = k;
      }
    }
    if (best < 0) continue;
    const double from = std::max(best - 1, 0) / static_cast<double>(kSamples);
    const double to = std::min(best + 1, kSamples) / static_cast<double>(kSamples);
    const double refined = -maximise([&](double s) { return -bottom(seg, s); }, from, to);
    lowest = std::min({lowest, best_value, refined});
  }
  return lowest - flat.axis_distance_mm;
}

// F13-F14 by brute force: the largest min(envelope, uncut cylinder) over the face, first half.
double end_mill_error_by_envelope(const FlatSection& flat, int steps, double face_width_mm) {
  Path path;
  for (int i = 0; i <= 2 * steps; ++i) path.points.push_back(step_point(flat, steps, i));
  const double r2 = flat.part_radius_mm;
  const auto left = [&](double u) {
    const double uncut = std::sqrt((r2 - u) * (r2 + u)) - flat.axis_distance_mm;
    return std::min(envelope_height(flat, path, u), uncut);
  };
  constexpr int kGrid = 1000;
  const double half = face_width_mm / 2.0;
  int best = 0;
  double best_value = -1.0;
  for (int k = 0; k <= kGrid; ++k) {
    const double value = left(-half + half * k / kGrid);
    if (value > best_value) {
      best_value = value;
      best = k;
    }
  }
  const double from = -half + half * std::max(best - 1, 0) / kGrid;
  const double to = -half + half * std::min(best + 1, kGrid) / kGrid;
  return std::max(best_value, maximise(left, from, to));
}

TEST(Flatness, PointToolMatchesTheRootOfF11InEverySegment) {
  for (const FlatSection& flat : {kPaper, FlatSection{25.0, 20.0, 0.0}, FlatSection{5.0, 1.0, 0.0},
                                  FlatSection{100.0, 99.9, 0.0}}) {
    for (const int n : {1, 2, 5, 10, 37}) {
      const double expected = point_tool_error_by_root(flat, n);
      EXPECT_NEAR(error_of(flat, n), expected, 1e-9 * expected + 1e-15)
          << "d " << flat.axis_distance_mm << " N " << n;
    }
  }
}

TEST(Flatness, WorkedExamplePointToolLeavesThreeMicrometres) {
  // Section 9: 2.9531 um at N = 10.
  EXPECT_NEAR(error_of(kPaper, 10) * 1000.0, 2.9531, 0.5e-4);
}

TEST(Flatness, EndMillMatchesTheBruteForceEnvelopeOfTheToolCircles) {
  // Section 9: R5, N = 4: 21.77 um.
  const double paper = end_mill_error_by_envelope(kPaperR5, 4, width_of(kPaperR5));
  EXPECT_NEAR(paper * 1000.0, 21.77, 0.005);
  EXPECT_NEAR(error_of(kPaperR5, 4), paper, 1e-9);
  for (const FlatSection& flat : {FlatSection{25.0, 20.0, 8.0}, FlatSection{10.0, 6.0, 2.0}}) {
    for (const int n : {2, 6}) {
      EXPECT_NEAR(error_of(flat, n), end_mill_error_by_envelope(flat, n, width_of(flat)), 1e-9)
          << "d " << flat.axis_distance_mm << " N " << n;
    }
  }
}

TEST(Flatness, FaceWidthLimitsTheSearchOnAPolygon) {
  // A hexagon with sharp corners (alpha_e = 35.7 deg > 30): only |u| <= w/2 = d tan 30 counts.
  const FlatSection hexagon{16.0, 13.0, 4.0};
  const double face = 2.0 * 13.0 * std::tan(std::numbers::pi / 6.0);
  EXPECT_NEAR(flatness_error_mm(hexagon, face, 3), end_mill_error_by_envelope(hexagon, 3, face),
              1e-9);
}

TEST(Flatness, ThePointToolNeverGougesAndTheErrorIsNeverNegative) {
  // F11: the spiral r_lin(a) cos a stays at or above d everywhere between the step points.
  for (const FlatSection& flat :
       {kPaper, FlatSection{25.0, 1.0, 0.0}, FlatSection{3.0, 2.999, 0.0}}) {
    for (const int n : {1, 3, 50}) {
      for (int i = 0; i < 2 * n; ++i) {
        const StepPoint p0 = step_point(flat, n, i);
        const StepPoint p1 = step_point(flat, n, i + 1);
        for (int k = 0; k <= 100; ++k) {
          const double s = k / 100.0;
          const double r = p0.x + s * (p1.x - p0.x);
          const double a = p0.alpha + s * (p1.alpha - p0.alpha);
          ASSERT_GE(r * std::cos(a) - flat.axis_distance_mm, -1e-12 * flat.part_radius_mm)
              << "d " << flat.axis_distance_mm << " N " << n << " i " << i << " s " << s;
        }
      }
      EXPECT_GE(error_of(flat, n), 0.0);
    }
  }
  // The end mill's envelope: nowhere below the flat either.
  Path path;
  for (int i = 0; i <= 8; ++i) path.points.push_back(step_point(kPaperR5, 4, i));
  for (int k = 0; k <= 200; ++k) {
    const double u = -5.5 + 11.0 * k / 200.0;
    EXPECT_GE(envelope_height(kPaperR5, path, u), -1e-12) << u;
  }
}

TEST(Flatness, EstimateOverEstimatesTheWorkedExamples) {
  // F15, section 4: 3.021 um vs 2.953 um; 25.18 um vs 21.77 um.
  const double point = flatness_error_estimate_mm(kPaper, 10);
  EXPECT_NEAR(point * 1000.0, 3.021, 0.5e-3);
  EXPECT_GT(point, error_of(kPaper, 10));
  const double mill = flatness_error_estimate_mm(kPaperR5, 4);
  EXPECT_NEAR(mill * 1000.0, 25.18, 0.005);
  EXPECT_GT(mill, error_of(kPaperR5, 4));
  // The closed form itself.
  const double alpha_e = std::acos(15.0 / 16.0);
  EXPECT_NEAR(
      point,
      15.0 * std::pow(alpha_e / 10.0, 2) * (1.0 + 2.0 * std::pow(std::tan(alpha_e), 2)) / 8.0,
      1e-15);
}

// F16 by its definition: every smaller N misses the tolerance, this one meets it.
void expect_smallest(const FlatSection& flat, double tolerance, int found) {
  for (int n = 1; n < found; ++n) {
    ASSERT_GT(error_of(flat, n), tolerance) << "N " << n << " already meets it";
  }
  EXPECT_LE(error_of(flat, found), tolerance);
}

TEST(Flatness, StepsForToleranceIsTheSmallestNThatMeetsIt) {
  const double width = width_of(kPaper);
  // A tolerance equal to error(7) is met by 7, not by 6; just below it needs 8.
  const double at_seven = error_of(kPaper, 7);
  EXPECT_EQ(steps_for_tolerance(kPaper, width, at_seven), 7);
  EXPECT_EQ(steps_for_tolerance(kPaper, width, std::nextafter(at_seven, 0.0)), 8);
  // A loose tolerance: one step.
  EXPECT_EQ(steps_for_tolerance(kPaper, width, 1.0), 1);
  for (const double tolerance : {1e-3, 2.9531e-3, 1e-5}) {
    const auto found = steps_for_tolerance(kPaper, width, tolerance);
    ASSERT_TRUE(found.has_value()) << tolerance;
    expect_smallest(kPaper, tolerance, *found);
  }
}

TEST(Flatness, StepsForToleranceAboveFortyAreFoundByBisectionAndStillTheSmallest) {
  // 0.1 um on the worked example needs about 10 sqrt(29.5) = 55 steps; error(40) misses it.
  const double width = width_of(kPaper);
  ASSERT_GT(error_of(kPaper, 40), 1e-4);
  const auto found = steps_for_tolerance(kPaper, width, 1e-4);
  ASSERT_TRUE(found.has_value());
  EXPECT_GT(*found, 40);
  expect_smallest(kPaper, 1e-4, *found);
  // The same with an end mill and a tolerance met exactly at some N > 40.
  const double at_hundred = error_of(kPaperR5, 100);
  const auto exact = steps_for_tolerance(kPaperR5, width, at_hundred);
  ASSERT_TRUE(exact.has_value());
  EXPECT_EQ(*exact, 100);
  EXPECT_EQ(steps_for_tolerance(kPaperR5, width, error_of(kPaperR5, 1000)), 1000);
}

TEST(Flatness, ToleranceThatNoThousandStepsMeetIsUnmet) {
  // D1000, t = 400 (alpha_e = 78.5 deg), R = 20: error(1000) is above 1 um.
  const FlatSection deep{500.0, 100.0, 20.0};
  const double width = width_of(deep);
  const double at_most = error_of(deep, kMaxSteps);
  ASSERT_GT(at_most, 1e-6);
  EXPECT_FALSE(steps_for_tolerance(deep, width, 1e-6).has_value());
  EXPECT_FALSE(steps_for_tolerance(deep, width, std::nextafter(at_most, 0.0)).has_value());
  EXPECT_EQ(steps_for_tolerance(deep, width, at_most), kMaxSteps);
}

}  // namespace
}  // namespace cutcalc::domain::lathe_flat
