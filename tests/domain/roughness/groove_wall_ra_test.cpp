// Ra and the bearing curve of the groove side wall profile, spec roughness.md R.7 (R9-R14): the
// area integral R11, the mean line R10, Ra R12 and the material ratio R13 against the raw upper
// envelope of two tool positions sampled finely (the spec's second method), the printed facts,
// phi1 = 0, the bearing curve R14 and its ends.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "domain/common/numeric.h"
#include "domain/common/result.h"
#include "domain/roughness/crest_branches.h"
#include "domain/roughness/groove_wall.h"
#include "domain/roughness/groove_wall_bearing.h"
#include "domain/roughness/pitch_profile.h"
#include "domain/roughness/roughness_test_support.h"

namespace {

using cutcalc::domain::kRadPerDeg;
using cutcalc::domain::roughness::BearingPoint;
using cutcalc::domain::roughness::compute_groove_wall_bearing_curve;
using cutcalc::domain::roughness::compute_groove_wall_roughness;
using cutcalc::domain::roughness::CrestBranch;
using cutcalc::domain::roughness::GrooveWallParams;
namespace roughness_detail = cutcalc::domain::roughness::detail;

using cutcalc::test::roughness::wall_printed;

double ra_um(double S, double rho, double phi1_deg) {
  const auto result = compute_groove_wall_roughness(GrooveWallParams{S, rho, phi1_deg, {}});
  EXPECT_TRUE(result.ok()) << "S " << S << " rho " << rho << " phi1 " << phi1_deg;
  return result.ok() ? result.value().ra_um : std::numeric_limits<double>::quiet_NaN();
}

std::vector<BearingPoint> bearing(double S, double rho, double phi1_deg, int n) {
  const auto result = compute_groove_wall_bearing_curve(GrooveWallParams{S, rho, phi1_deg, {}}, n);
  EXPECT_TRUE(result.ok()) << "S " << S << " rho " << rho << " phi1 " << phi1_deg;
  return result.ok() ? result.value() : std::vector<BearingPoint>{};
}

roughness_detail::PitchProfile profile(double S, double rho, double phi1_deg) {
  return roughness_detail::pitch_profile(S, rho,
                                         roughness_detail::minor_edge_angle(phi1_deg * kRadPerDeg));
}

// Independent oracle (R.3, R9): the tool's upper boundary with its corner at x = 0, the wall as
// the upper envelope of the previous (corner at 0) and current (corner at S) positions, the
// profile y = rho - wall sampled at the midpoints of `samples` cells. No formula of R9-R13 is used.
using cutcalc::test::roughness::tool_boundary;

std::vector<double> sampled_profile(double S, double rho, double phi1_deg, int samples) {
  const long double phi1 = phi1_deg * kRadPerDeg;
  std::vector<double> y(static_cast<std::size_t>(samples));
  for (int i = 0; i < samples; ++i) {
    const long double x = S * (i + 0.5L) / samples;
    const long double wall = std::max(tool_boundary(x, rho, phi1), tool_boundary(x - S, rho, phi1));
    y[static_cast<std::size_t>(i)] = static_cast<double>(rho - wall);
  }
  return y;
}

double sampled_mean(const std::vector<double>& y) {
  long double sum = 0.0L;
  for (const double v : y) sum += v;
  return static_cast<double>(sum / y.size());
}

double sampled_ra(const std::vector<double>& y) {
  const double mean = sampled_mean(y);
  long double sum = 0.0L;
  for (const double v : y) sum += std::fabs(v - mean);
  return static_cast<double>(sum / y.size());
}

double sampled_material_ratio(const std::vector<double>& y, double level) {
  const auto count = std::count_if(y.begin(), y.end(), [level](double v) { return v >= level; });
  return static_cast<double>(count) / static_cast<double>(y.size());
}

// The sampling step of the oracle: S / kSamples (its error in Ra is of that relative order).
constexpr int kSamples = 100000;

// Valid geometries over all three branches, random ones (as the Rz oracle test draws them).
struct Geometry {
  double S, rho, phi1_deg;
};

std::vector<Geometry> random_geometries(int count) {
  std::mt19937_64 rng(20261127);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  // Branch B is narrow for a large phi1: some of its geometries by hand, the paper's first.
  std::vector<Geometry> out = {{0.12, 0.3, 2.0}, {0.48, 0.3, 2.0}, {2.0, 0.3, 2.0},
                               {0.2, 0.4, 10.0}, {0.3, 0.3, 20.0}, {1.0, 0.5, 5.0}};
  for (int i = 0; i < count; ++i) {
    const double rho = 0.05 * std::pow(40.0, unit(rng));     // 0.05 .. 2 mm
    const double phi1_deg = 0.5 + 89.0 * unit(rng);          // 0.5 .. 89.5 deg
    const double S = 1e-2 * rho * std::pow(1e4, unit(rng));  // 1e-2 rho .. 100 rho
    out.push_back({S, rho, phi1_deg});
  }
  return out;
}

// R11 against Simpson's rule on the arc height, below and above the series switch (th = 0.1).
TEST(GrooveWallRa, NoseArcAreaIsTheIntegralOfTheArcHeight) {
  const double rho = 0.3;
  for (const double a : {1e-5, 0.003, 0.02, 0.0299, 0.0301, 0.1, 0.25, 0.3}) {
    const int n = 20000;  // even
    const double h = a / n;
    long double sum = 0.0L;
    for (int i = 0; i <= n; ++i) {
      const long double u = i * static_cast<long double>(h);
      // rho - sqrt(rho^2 - u^2) without its cancellation near u = 0.
      const long double y = u * u / (rho + std::sqrt(std::max(rho * rho - u * u, 0.0L)));
      sum += (i == 0 || i == n ? 1 : (i % 2 == 1 ? 4 : 2)) * y;
    }
    const double want = static_cast<double>(sum * h / 3.0L);
    // Simpson is exact to ~1e-12 relative here except at a = rho, where the slope is infinite.
    const double tolerance = a == rho ? 1e-6 * want : 1e-10 * want;
    EXPECT_NEAR(roughness_detail::nose_arc_area(a, rho), want, tolerance) << "a " << a;
  }
  // The series branch keeps the relative accuracy of u^3 / (6 rho) for a tiny a.
  EXPECT_NEAR(roughness_detail::nose_arc_area(1e-6, 0.3), 1e-18 / 1.8, 1e-9 * 1e-18 / 1.8);
}

// R10 against the mean of the sampled profile, in all three branches.
TEST(GrooveWallRa, MeanLineIsTheMeanOfTheSampledProfile) {
  for (const Geometry& g : random_geometries(20)) {
    const auto y = sampled_profile(g.S, g.rho, g.phi1_deg, kSamples);
    const double want = sampled_mean(y);
    EXPECT_NEAR(roughness_detail::mean_line_height(profile(g.S, g.rho, g.phi1_deg)), want,
                3e-5 * want)
        << "S " << g.S << " rho " << g.rho << " phi1 " << g.phi1_deg;
  }
}

// R12 against the sampled profile's mean absolute deviation, in all three branches.
TEST(GrooveWallRa, RaIsTheMeanDeviationOfTheSampledProfile) {
  int counts[3] = {0, 0, 0};
  for (const Geometry& g : random_geometries(60)) {
    ++counts[static_cast<int>(profile(g.S, g.rho, g.phi1_deg).branch)];
    const double want = 1000.0 * sampled_ra(sampled_profile(g.S, g.rho, g.phi1_deg, kSamples));
    EXPECT_NEAR(ra_um(g.S, g.rho, g.phi1_deg), want, 3e-5 * want)
        << "S " << g.S << " rho " << g.rho << " phi1 " << g.phi1_deg;
  }
  EXPECT_GT(counts[0], 5);
  EXPECT_GT(counts[1], 5);
  EXPECT_GT(counts[2], 5);
}

// The facts of R.7: paper geometry rho 0.3, phi1 2 deg.
TEST(GrooveWallRa, ReproducesThePrintedValues) {
  EXPECT_NEAR(ra_um(0.12, 0.3, 2.0), 0.70803, wall_printed(1e-5));
  EXPECT_NEAR(ra_um(0.48, 0.3, 2.0), 3.51635, wall_printed(1e-5));
}

// A parabolic cusp: Rz / Ra -> 9 sqrt(3) / 4 as the pitch shrinks (branch A).
TEST(GrooveWallRa, SmallPitchesGiveTheParabolicRatio) {
  const double parabolic = 9.0 * std::numbers::sqrt3 / 4.0;
  for (const double S : {1e-3, 1e-5, 1e-7}) {
    const auto r = compute_groove_wall_roughness(GrooveWallParams{S, 0.3, 30.0, {}});
    ASSERT_TRUE(r.ok());
    EXPECT_NEAR(r.value().rz_um / r.value().ra_um, parabolic, 1e-5) << "S " << S;
  }
}

// phi1 = 0: the wall is flat, Ra = 0 and the whole pitch is material at every depth.
TEST(GrooveWallRa, ZeroMinorEdgeAngleIsAFlatWall) {
  EXPECT_EQ(ra_um(0.1, 0.3, 0.0), 0.0);
  for (const BearingPoint& point : bearing(0.1, 0.3, 0.0, 3)) {
    EXPECT_EQ(point.depth_um, 0.0);
    EXPECT_EQ(point.material_ratio, 1.0);
  }
  EXPECT_EQ(bearing(0.1, 0.3, 0.0, 3).size(), 3u);
}

// Ra scales with the geometry, and the areas (which grow as S^2) never overflow while Rz and Ra
// are finite.
TEST(GrooveWallRa, RaScalesWithTheGeometryWithoutOverflow) {
  const double base = ra_um(0.12, 0.3, 2.0);
  for (const double scale : {1e-4, 8.0, 1e6, 1e200}) {
    EXPECT_NEAR(ra_um(0.12 * scale, 0.3 * scale, 2.0), base * scale, 1e-12 * base * scale)
        << "scale " << scale;
  }
  const double huge = ra_um(1e200, 0.3, 45.0);
  EXPECT_TRUE(std::isfinite(huge));
  EXPECT_NEAR(huge, 1e203 / 4.0, 1e-9 * 1e203);  // a saw-tooth: Ra = Rz / 4
}

// R13 against the sampled profile's fraction at or above the level, in all three branches.
TEST(GrooveWallBearing, MaterialRatioIsTheSampledFraction) {
  for (const Geometry& g : random_geometries(30)) {
    const auto y = sampled_profile(g.S, g.rho, g.phi1_deg, kSamples);
    const roughness_detail::PitchProfile p = profile(g.S, g.rho, g.phi1_deg);
    for (const double fraction : {0.0, 0.1, 0.37, 0.5, 0.81, 0.99, 1.0, 1.5}) {
      const double c = fraction * p.Rz;
      const double want = fraction >= 1.0 ? 1.0 : sampled_material_ratio(y, p.Rz - c);
      EXPECT_NEAR(roughness_detail::material_ratio(p, c), want, 3.0 / kSamples)
          << "S " << g.S << " rho " << g.rho << " phi1 " << g.phi1_deg << " c/Rz " << fraction;
    }
  }
}

// R14: n points at depths Rz k / n, the material ratio rising to 1 at the last.
TEST(GrooveWallBearing, CurveRunsFromTheCrestToTheValleys) {
  for (const Geometry& g : random_geometries(30)) {
    const double rz_um = compute_groove_wall_roughness({g.S, g.rho, g.phi1_deg, {}}).value().rz_um;
    for (const int n : {2, 5, 1000}) {
      const auto curve = bearing(g.S, g.rho, g.phi1_deg, n);
      ASSERT_EQ(curve.size(), static_cast<std::size_t>(n));
      for (int k = 1; k <= n; ++k) {
        const BearingPoint& point = curve[static_cast<std::size_t>(k - 1)];
        EXPECT_NEAR(point.depth_um, rz_um * k / n, 1e-12 * rz_um);
        EXPECT_GE(point.material_ratio, 0.0);
        EXPECT_LE(point.material_ratio, 1.0);
        if (k > 1) {
          EXPECT_GE(point.material_ratio, curve[static_cast<std::size_t>(k - 2)].material_ratio);
        }
      }
      EXPECT_EQ(curve.back().depth_um, rz_um);
      EXPECT_EQ(curve.back().material_ratio, 1.0);
    }
  }
}

// The target plays no part in Ra or the bearing curve.
TEST(GrooveWallBearing, TargetChangesNothing) {
  const auto plain = compute_groove_wall_roughness(GrooveWallParams{0.12, 0.3, 2.0, {}});
  const auto with_target = compute_groove_wall_roughness(GrooveWallParams{0.12, 0.3, 2.0, 13.2});
  ASSERT_TRUE(plain.ok() && with_target.ok());
  EXPECT_EQ(plain.value().ra_um, with_target.value().ra_um);
  const auto curve = compute_groove_wall_bearing_curve(GrooveWallParams{0.12, 0.3, 2.0, 13.2}, 5);
  ASSERT_TRUE(curve.ok());
  EXPECT_EQ(curve.value().back().material_ratio, 1.0);
}

}  // namespace
