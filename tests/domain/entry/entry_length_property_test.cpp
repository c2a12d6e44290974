// Property tests: compute_entry_length (unified formula E10-E12) against the independent closed
// forms E13-E22 (closed_forms.h) on thousands of random cases per contour family, entry and exit.
// Spec: shared/domain/entry-and-main-time.md.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iostream>
#include <optional>
#include <random>
#include <sstream>
#include <string>

#include "domain/common/golden_section.h"
#include "domain/entry/closed_forms.h"
#include "domain/entry/entry_length.h"
#include "domain/entry/entry_test_support.h"

namespace {

namespace oracle = cutcalc::test::entry_oracle;
using cutcalc::domain::ErrorCode;
using cutcalc::domain::entry::compute_entry_length;
using cutcalc::domain::entry::Contour;
using cutcalc::domain::entry::EntryLengthParams;
using cutcalc::test::outcome;

// Absolute tolerance of the comparison. Every random magnitude below stays under ~1000 mm, where
// one double rounding is ~1e-13 mm; the closed forms and E10-E12 reach the same value by different
// but well-conditioned operations (random cases never sit within 1e-12 of a tangency, where the
// square roots would amplify rounding), so 1e-9 mm leaves three orders of margin.
using cutcalc::test::kTol;
// |steady travel| below this is too close to the E23 boundary to say which side the service falls.
constexpr double kStrokeBoundary = 1e-9;

enum class Kind { straight90, inclined, convex_full, convex_partial, concave, wall };

const char* kind_name(Kind kind) {
  switch (kind) {
    case Kind::straight90:
      return "straight90";
    case Kind::inclined:
      return "straight_inclined";
    case Kind::convex_full:
      return "convex_full";
    case Kind::convex_partial:
      return "convex_partial";
    case Kind::concave:
      return "concave";
    case Kind::wall:
      return "wall";
  }
  return "?";
}

// A contour as the tests see it: enough to build the API Contour and to evaluate the oracle.
struct Shape {
  Kind kind = Kind::straight90;
  double width = 0.0;   // B (part width; 2R for convex_full)
  double radius = 0.0;  // R
  double angle = 90.0;  // alpha
};

Contour to_contour(const Shape& s) {
  using namespace cutcalc::test;
  switch (s.kind) {
    case Kind::straight90:
      return straight_contour(s.width, 90.0);
    case Kind::inclined:
      return straight_contour(s.width, s.angle);
    case Kind::convex_full:
      return convex_contour(s.radius);  // width_mm left out: B = 2R (E3)
    case Kind::convex_partial:
      return convex_contour(s.radius, s.width);
    case Kind::concave:
      return concave_contour(s.radius, s.width);
    case Kind::wall:
      return wall_contour(s.width);
  }
  return {};
}

std::string describe(const Shape& s) {
  std::ostringstream out;
  out.precision(17);
  out << kind_name(s.kind) << "{B=" << s.width << " R=" << s.radius << " alpha=" << s.angle << "}";
  return out.str();
}

std::optional<oracle::EntryForm> oracle_entry(const Shape& s, double D, double K, double approach) {
  switch (s.kind) {
    case Kind::straight90:
      return oracle::straight90_entry(D, s.width, K, approach);
    case Kind::inclined:
      return oracle::straight_entry(D, s.width, K, s.angle, approach);
    case Kind::convex_full:
      return oracle::convex_full_entry(D, s.radius, K, approach);
    case Kind::convex_partial:
      return oracle::convex_entry(D, s.radius, s.width, K, approach);
    case Kind::concave:
      return oracle::concave_entry(D, s.radius, s.width, K, approach);
    case Kind::wall:
      break;
  }
  return std::nullopt;
}

std::optional<oracle::ExitForm> oracle_exit(const Shape& s, double D, double K) {
  switch (s.kind) {
    case Kind::straight90:
      return oracle::straight90_exit(D, s.width, K);
    case Kind::inclined:
      return oracle::straight_exit(D, s.width, K, s.angle);
    case Kind::convex_full:
      return oracle::convex_full_exit(D, s.radius, K);
    case Kind::convex_partial:
      return oracle::convex_exit(D, s.radius, s.width, K);
    case Kind::concave:
      return oracle::concave_exit(D, s.radius, s.width, K);
    case Kind::wall:
      return oracle::wall_exit(D, s.width, K);
  }
  return std::nullopt;
}

class Random {
 public:
  explicit Random(std::uint64_t seed) : gen_(seed) {}
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(gen_);
  }
  double log_uniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
  bool chance(double p) { return uniform(0.0, 1.0) < p; }
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(gen_); }

 private:
  std::mt19937_64 gen_;
};

double random_angle(Random& rng) {
  double alpha = rng.uniform(3.0, 177.0);
  if (alpha == 90.0) {
    alpha = 91.0;
  }
  return alpha;
}

Shape random_entry(Kind kind, Random& rng) {
  Shape s;
  s.kind = kind;
  switch (kind) {
    case Kind::straight90:
      s.width = rng.log_uniform(1.0, 400.0);
      break;
    case Kind::inclined:
      s.width = rng.log_uniform(1.0, 400.0);
      s.angle = random_angle(rng);
      break;
    case Kind::convex_full:
      s.radius = rng.log_uniform(0.5, 300.0);
      s.width = 2.0 * s.radius;
      break;
    case Kind::convex_partial:
      s.radius = rng.log_uniform(0.5, 300.0);
      s.width = 2.0 * s.radius * rng.uniform(0.05, 0.95);
      break;
    case Kind::concave:
      s.width = rng.log_uniform(1.0, 400.0);
      // R >= h; 5% semicircular notches (R = h exactly, c0 = 0).
      s.radius = rng.chance(0.05) ? s.width / 2.0 : s.width / 2.0 / rng.uniform(0.1, 1.0);
      break;
    case Kind::wall:
      break;
  }
  return s;
}

// An exit contour of the same part width B (any kind, so that mixed pairs are covered too).
Shape random_exit(double part_width, Random& rng) {
  Shape s;
  s.width = part_width;
  const double h = part_width / 2.0;
  switch (rng.pick(6)) {
    case 0:
      s.kind = Kind::straight90;
      break;
    case 1:
      s.kind = Kind::inclined;
      s.angle = random_angle(rng);
      break;
    case 2:
      s.kind = Kind::wall;
      break;
    case 3:
      s.kind = Kind::convex_full;
      s.radius = h;  // 2R = B exactly
      break;
    case 4:
      s.kind = Kind::convex_partial;
      s.radius = h / rng.uniform(0.1, 0.95);
      break;
    default:
      s.kind = Kind::concave;
      s.radius = rng.chance(0.1) ? h : h / rng.uniform(0.1, 1.0);
      break;
  }
  return s;
}

struct RandomCase {
  Shape entry;
  Shape exit;
  double D = 0.0;
  double K = 0.0;
  double approach = 2.0;
  double length = 0.0;
  double extra = 0.0;
  double overrun = 2.0;
};

RandomCase random_case(Kind entry_kind, bool wall_exit, Random& rng) {
  RandomCase c;
  if (entry_kind == Kind::wall) {
    // Wall family: any entry kind, exit = wall.
    static constexpr std::array<Kind, 5> kinds{Kind::straight90, Kind::inclined, Kind::convex_full,
                                               Kind::convex_partial, Kind::concave};
    entry_kind = kinds[static_cast<std::size_t>(rng.pick(5))];
  }
  c.entry = random_entry(entry_kind, rng);
  if (wall_exit) {
    c.exit.kind = Kind::wall;
    c.exit.width = c.entry.width;
  } else {
    c.exit = random_exit(c.entry.width, rng);
  }
  const double r = rng.log_uniform(0.25, 200.0);
  c.D = 2.0 * r;
  const double h = c.entry.width / 2.0;
  const double reach = (h + r) * 1.08;  // ~7% of the offsets miss the strip (no contact)
  c.K = rng.chance(0.08) ? 0.0 : rng.uniform(-reach, reach);
  c.approach = rng.uniform(0.0, 5.0);
  c.length = rng.log_uniform(1.0, 2000.0);
  c.extra = rng.chance(0.5) ? 0.0 : rng.uniform(0.0, 50.0);
  c.overrun = rng.uniform(0.0, 5.0);
  return c;
}

std::string describe(const RandomCase& c) {
  std::ostringstream out;
  out.precision(17);
  out << "entry=" << describe(c.entry) << " exit=" << describe(c.exit) << " D=" << c.D
      << " K=" << c.K << " L_pod=" << c.approach << " L=" << c.length << " L1=" << c.extra
      << " L_per=" << c.overrun;
  return out.str();
}

struct Tally {
  int total = 0;
  int compared = 0;
  int no_contact = 0;
  int short_stroke = 0;
  int boundary = 0;
  int mismatches = 0;
  double max_diff = 0.0;  // largest |service - closed form| over every compared value
};

void report_mismatch(Tally& tally, const RandomCase& c, const std::string& what) {
  ++tally.mismatches;
  if (tally.mismatches <= 15) {
    ADD_FAILURE() << what << "\n  case: " << describe(c);
  }
}

void check_value(Tally& tally, const RandomCase& c, const char* field, double got, double expected,
                 bool& case_failed) {
  tally.max_diff = std::max(tally.max_diff, std::abs(got - expected));
  if (!(std::abs(got - expected) <= kTol)) {
    std::ostringstream out;
    out.precision(17);
    out << field << ": got " << got << ", expected " << expected << " (diff " << got - expected
        << ")";
    if (!case_failed) {
      report_mismatch(tally, c, out.str());
    } else if (tally.mismatches <= 15) {
      ADD_FAILURE() << out.str();
    }
    case_failed = true;
  }
}

// Runs one case through the service and the oracle and records the outcome.
void check_case(const RandomCase& c, Tally& tally) {
  ++tally.total;
  const EntryLengthParams params = cutcalc::test::entry_exit(
      c.D, c.K, to_contour(c.entry), to_contour(c.exit), c.length, c.approach, c.extra, c.overrun);
  const auto result = compute_entry_length(params);

  const auto entry = oracle_entry(c.entry, c.D, c.K, c.approach);
  const auto exit = oracle_exit(c.exit, c.D, c.K);
  if (!entry || !exit) {
    ++tally.no_contact;
    if (result.ok() || result.error().code != ErrorCode::no_contact) {
      report_mismatch(tally, c, "expected no_contact, got " + outcome(result));
    }
    return;
  }
  const bool wall = c.exit.kind == Kind::wall;
  const double overrun = wall ? 0.0 : c.overrun;  // E22
  // E23: steady travel L + L1 + L_per - x_cs - X_k.
  const double steady = c.length + c.extra + overrun - entry->saturation_x_mm - exit->end_x_mm;
  if (std::abs(steady) <= kStrokeBoundary) {
    ++tally.boundary;
    return;
  }
  if (steady < 0.0) {
    ++tally.short_stroke;
    if (result.ok() || result.error().code != ErrorCode::stroke_shorter_than_entry) {
      std::ostringstream out;
      out << "expected stroke_shorter_than_entry (steady travel " << steady << "), got "
          << outcome(result);
      report_mismatch(tally, c, out.str());
    }
    return;
  }
  if (!result.ok()) {
    report_mismatch(tally, c, "expected a value, got " + outcome(result));
    return;
  }
  ++tally.compared;
  const auto& got = result.value();
  bool failed = false;
  check_value(tally, c, "engagement_length_mm", got.engagement_length_mm, entry->engagement_mm,
              failed);
  check_value(tally, c, "entry_length_mm", got.entry_length_mm, c.approach + entry->engagement_mm,
              failed);
  check_value(tally, c, "start.x_mm", got.start.x_mm, entry->start_x_mm, failed);
  check_value(tally, c, "start.y_mm", got.start.y_mm, entry->start_y_mm, failed);
  check_value(tally, c, "steady_width_mm", got.steady_width_mm, entry->steady_width_mm, failed);
  if (!got.exit) {
    report_mismatch(tally, c, "exit result missing");
    return;
  }
  check_value(tally, c, "end.x_mm", got.exit->end.x_mm, exit->end_x_mm, failed);
  check_value(tally, c, "end.y_mm", got.exit->end.y_mm, exit->end_y_mm, failed);
  // E9
  const double stroke = c.length + c.extra + entry->start_x_mm - exit->end_x_mm + overrun;
  check_value(tally, c, "working_stroke_mm", got.exit->working_stroke_mm, stroke, failed);
}

void print_tally(const char* family, const Tally& t) {
  std::cout << "[ property ] " << family << ": " << t.total << " cases, " << t.compared
            << " compared, " << t.no_contact << " no_contact, " << t.short_stroke
            << " stroke_shorter_than_entry, " << t.boundary << " on the E23 boundary, "
            << t.mismatches << " mismatches, max |diff| " << t.max_diff << " mm\n";
}

// Most cases must really be compared (a property test that skips everything cannot fail), and the
// rejections must be the minority they were designed to be.
void expect_coverage(const Tally& t) {
  EXPECT_EQ(t.mismatches, 0);
  EXPECT_GE(t.compared, t.total * 7 / 10) << "too few cases were compared";
  EXPECT_GT(t.no_contact, 0) << "no no-contact case was generated: the generator is off";
  EXPECT_LE(t.boundary, 2);
}

constexpr int kCasesPerFamily = 5000;

}  // namespace

TEST(EntryLengthProperty, StraightPerpendicularMatchesE13) {
  Random rng(0x5EED0001u);
  Tally tally;
  std::array<int, 4> compared_by_case{};
  for (int i = 0; i < kCasesPerFamily; ++i) {
    const RandomCase c = random_case(Kind::straight90, false, rng);
    const int before = tally.compared;
    check_case(c, tally);
    if (tally.compared > before) {
      const auto sub = oracle::straight90_case(c.D / 2.0, c.entry.width / 2.0, c.K);
      ++compared_by_case[static_cast<std::size_t>(sub)];
    }
  }
  print_tally("straight, alpha = 90", tally);
  std::cout << "[ property ]   S1..S4 compared: " << compared_by_case[0] << " "
            << compared_by_case[1] << " " << compared_by_case[2] << " " << compared_by_case[3]
            << "\n";
  expect_coverage(tally);
  for (int n : compared_by_case) {
    EXPECT_GE(n, 100) << "a sub-case S1-S4 is under-sampled";
  }
}

TEST(EntryLengthProperty, StraightInclinedMatchesE14E16) {
  Random rng(0x5EED0002u);
  Tally tally;
  int band_inside = 0;
  for (int i = 0; i < kCasesPerFamily; ++i) {
    const RandomCase c = random_case(Kind::inclined, false, rng);
    const int before = tally.compared;
    check_case(c, tally);
    if (tally.compared > before && std::abs(c.K) + c.D / 2.0 <= c.entry.width / 2.0) {
      ++band_inside;
    }
  }
  print_tally("straight, inclined", tally);
  std::cout << "[ property ]   band inside the strip (E15 domain): " << band_inside << "\n";
  expect_coverage(tally);
  EXPECT_GE(band_inside, 200);
}

TEST(EntryLengthProperty, ConvexArcFullWidthMatchesE18E19) {
  Random rng(0x5EED0003u);
  Tally tally;
  std::array<int, 4> compared_by_case{};
  for (int i = 0; i < kCasesPerFamily; ++i) {
    const RandomCase c = random_case(Kind::convex_full, false, rng);
    const int before = tally.compared;
    check_case(c, tally);
    if (tally.compared > before) {
      const auto sub = oracle::convex_full_case(c.D / 2.0, c.entry.radius, c.K);
      ++compared_by_case[static_cast<std::size_t>(sub)];
    }
  }
  print_tally("convex arc, full width", tally);
  std::cout << "[ property ]   cases A..D compared: " << compared_by_case[0] << " "
            << compared_by_case[1] << " " << compared_by_case[2] << " " << compared_by_case[3]
            << "\n";
  expect_coverage(tally);
  for (int n : compared_by_case) {
    EXPECT_GE(n, 100) << "a case A-D of E18 is under-sampled";
  }
}

TEST(EntryLengthProperty, ConvexArcPartialWidthMatchesE17E19) {
  Random rng(0x5EED0004u);
  Tally tally;
  for (int i = 0; i < kCasesPerFamily; ++i) {
    check_case(random_case(Kind::convex_partial, false, rng), tally);
  }
  print_tally("convex arc, partial width", tally);
  expect_coverage(tally);
}

TEST(EntryLengthProperty, ConcaveArcMatchesE20E21) {
  Random rng(0x5EED0005u);
  Tally tally;
  int interior_max = 0;
  for (int i = 0; i < kCasesPerFamily; ++i) {
    const RandomCase c = random_case(Kind::concave, false, rng);
    const int before = tally.compared;
    check_case(c, tally);
    if (tally.compared > before &&
        oracle::concave_entry_max_is_interior(c.D, c.entry.radius, c.entry.width, c.K)) {
      ++interior_max;
    }
  }
  print_tally("concave arc", tally);
  std::cout << "[ property ]   maximum of psi at the interior point y_c: " << interior_max << "\n";
  expect_coverage(tally);
  EXPECT_GE(interior_max, 100) << "the interior maximum (r > R) is under-sampled";
}

TEST(EntryLengthProperty, WallExitMatchesE22) {
  Random rng(0x5EED0006u);
  Tally tally;
  for (int i = 0; i < kCasesPerFamily; ++i) {
    check_case(random_case(Kind::wall, true, rng), tally);
  }
  print_tally("wall exit", tally);
  expect_coverage(tally);
}

// ---- Oracle self-check --------------------------------------------------------------------------
// The oracle's closed forms against a sampled evaluation of the definition (E10/E11: first contact
// at min psi, saturation at max psi, end at max phi over the band), so that a disagreement with the
// service can be pinned on the right side.

namespace {

// Contour functions of section 3 in the internal frame (entry: W = {x >= e(y)}, exit: x <= f(y)).
double contour_entry_x(const Shape& s, double y) {
  const double h = s.width / 2.0;
  switch (s.kind) {
    case Kind::straight90:
    case Kind::inclined:
      return (y + h) * oracle::cot_deg(s.kind == Kind::straight90 ? 90.0 : s.angle);
    case Kind::convex_full:
    case Kind::convex_partial:
      return s.radius - std::sqrt(std::max(0.0, s.radius * s.radius - y * y));
    case Kind::concave:
      return std::sqrt(std::max(0.0, s.radius * s.radius - y * y)) -
             std::sqrt(std::max(0.0, s.radius * s.radius - h * h));
    case Kind::wall:
      break;
  }
  return 0.0;
}

double contour_exit_x(const Shape& s, double y) {
  const double h = s.width / 2.0;
  switch (s.kind) {
    case Kind::straight90:
    case Kind::inclined:
      return (y + h) * oracle::cot_deg(s.kind == Kind::straight90 ? 90.0 : s.angle);
    case Kind::convex_full:
    case Kind::convex_partial:
      return std::sqrt(std::max(0.0, s.radius * s.radius - y * y)) - s.radius;
    case Kind::concave:
      return std::sqrt(std::max(0.0, s.radius * s.radius - h * h)) -
             std::sqrt(std::max(0.0, s.radius * s.radius - y * y));
    case Kind::wall:
      break;
  }
  return 0.0;
}

// Extremum of f on [a, b] by dense sampling and golden-section refinement around the best sample.
double sampled_extremum(const std::function<double(double)>& f, double a, double b, bool maximum) {
  const int n = 4000;
  const double sign = maximum ? -1.0 : 1.0;
  const auto g = [&](double y) { return sign * f(y); };
  int best = 0;
  double best_value = g(a);
  for (int i = 1; i <= n; ++i) {
    const double y = a + (b - a) * i / n;
    const double v = g(y);
    if (v < best_value) {
      best_value = v;
      best = i;
    }
  }
  const double lo = a + (b - a) * std::max(0, best - 1) / n;
  const double hi = a + (b - a) * std::min(n, best + 1) / n;
  const double width = 1e-14 * (1.0 + std::max(std::abs(lo), std::abs(hi)));
  const auto s = cutcalc::domain::golden_section_minimum(g, lo, hi, width, 200);
  best_value = std::min({best_value, g(s.a), g(s.b), s.smallest_value(), g(s.midpoint())});
  return sign * best_value;
}

}  // namespace

TEST(EntryOracle, ClosedFormsMatchSampledDefinition) {
  Random rng(0x5EED0007u);
  constexpr std::array<Kind, 5> kinds{Kind::straight90, Kind::inclined, Kind::convex_full,
                                      Kind::convex_partial, Kind::concave};
  int checked = 0;
  for (Kind kind : kinds) {
    for (int i = 0; i < 300; ++i) {
      const RandomCase c = random_case(kind, false, rng);
      const auto entry = oracle_entry(c.entry, c.D, c.K, c.approach);
      const auto exit = oracle_exit(c.exit, c.D, c.K);
      const double r = c.D / 2.0;
      const double h = c.entry.width / 2.0;  // every generated arc has B <= 2R
      const double a = std::max(c.K - r, -h);
      const double b = std::min(c.K + r, h);
      ASSERT_EQ(entry.has_value(), b - a > 0.0) << describe(c);
      if (!entry) {
        continue;
      }
      const auto chord = [&](double y) {
        return std::sqrt(std::max(0.0, r * r - (y - c.K) * (y - c.K)));
      };
      const auto psi = [&](double y) { return contour_entry_x(c.entry, y) - chord(y); };
      const auto phi = [&](double y) { return contour_exit_x(c.exit, y) - chord(y); };
      const double xc0 = sampled_extremum(psi, a, b, false);
      const double xcs = sampled_extremum(psi, a, b, true);
      // Sampling error and the sqrt singularity at the band ends: 1e-6 mm is ample.
      const double tol = 1e-6 * (1.0 + std::abs(xc0) + std::abs(xcs));
      EXPECT_NEAR(c.approach - entry->start_x_mm, xc0, tol) << describe(c);
      EXPECT_NEAR(entry->saturation_x_mm, xcs, tol) << describe(c);
      EXPECT_NEAR(entry->engagement_mm, xcs - xc0, tol) << describe(c);
      EXPECT_NEAR(entry->steady_width_mm, b - a, 1e-12 * (1.0 + h)) << describe(c);
      ASSERT_TRUE(exit.has_value()) << describe(c);
      if (c.exit.kind != Kind::wall) {
        const double end = -sampled_extremum(phi, a, b, true);
        EXPECT_NEAR(exit->end_x_mm, end, 1e-6 * (1.0 + std::abs(end))) << describe(c);
      }
      // The full-width table E18/E19 and the general E17/E19 must agree.
      if (c.entry.kind == Kind::convex_full) {
        const auto general =
            oracle::convex_entry(c.D, c.entry.radius, c.entry.width, c.K, c.approach);
        ASSERT_TRUE(general.has_value());
        EXPECT_NEAR(general->engagement_mm, entry->engagement_mm, 1e-9) << describe(c);
        EXPECT_NEAR(general->start_x_mm, entry->start_x_mm, 1e-9) << describe(c);
        const auto general_exit = oracle::convex_exit(c.D, c.entry.radius, c.entry.width, c.K);
        const auto full_exit = oracle::convex_full_exit(c.D, c.entry.radius, c.K);
        ASSERT_TRUE(general_exit && full_exit);
        EXPECT_NEAR(general_exit->end_x_mm, full_exit->end_x_mm, 1e-9) << describe(c);
      }
      // E13 is E14 at alpha = 90; E15 is E14 with the band inside the strip.
      if (c.entry.kind == Kind::straight90) {
        const auto e14 = oracle::straight_entry(c.D, c.entry.width, c.K, 90.0, c.approach);
        ASSERT_TRUE(e14.has_value());
        EXPECT_NEAR(e14->engagement_mm, entry->engagement_mm, 1e-9) << describe(c);
        EXPECT_NEAR(e14->start_x_mm, entry->start_x_mm, 1e-9) << describe(c);
      }
      if (c.entry.kind == Kind::inclined) {
        if (const auto e15 = oracle::straight_entry_band_inside(c.D, c.entry.width, c.K,
                                                                c.entry.angle, c.approach)) {
          EXPECT_NEAR(e15->engagement_mm, entry->engagement_mm, 1e-9) << describe(c);
          EXPECT_NEAR(e15->start_x_mm, entry->start_x_mm, 1e-9) << describe(c);
        }
      }
      ++checked;
    }
  }
  EXPECT_GE(checked, 1200);
}
