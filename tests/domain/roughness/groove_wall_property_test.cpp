// Groove side wall, spec roughness.md R7 and R8: Rz never decreases with the feed, and
// max_feed_mm is the exact largest feed whose crest height meets the target.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "domain/common/numeric.h"
#include "domain/roughness/crest_branches.h"
#include "domain/roughness/groove_wall.h"

namespace {

using cutcalc::domain::roughness::compute_groove_wall_roughness;
using cutcalc::domain::roughness::GrooveWallParams;
namespace roughness_detail = cutcalc::domain::roughness::detail;

using cutcalc::domain::kRadPerDeg;

const double kRhos[] = {0.1, 0.2, 0.3, 0.5, 0.8, 1.2};
const double kAngles[] = {0.0,  0.01, 0.1,  0.5,  1.0,  2.0,  5.0,  10.0,
                          20.0, 30.0, 45.0, 60.0, 75.0, 85.0, 89.0, 89.9};

double rz_mm(double S, double rho, double phi1_deg) {
  const auto result = compute_groove_wall_roughness(GrooveWallParams{S, rho, phi1_deg, {}});
  EXPECT_TRUE(result.ok());
  return result.ok() ? result.value().rz_um / 1000.0 : -1.0;
}

double max_feed_mm(double rho, double phi1_deg, double target_um, double feed = 0.1) {
  const auto result =
      compute_groove_wall_roughness(GrooveWallParams{feed, rho, phi1_deg, target_um});
  EXPECT_TRUE(result.ok() && result.value().max_feed_mm.has_value());
  return result.ok() && result.value().max_feed_mm ? *result.value().max_feed_mm : -1.0;
}

// A log grid of feeds 1e-4 .. 50 mm, plus points a relative 1e-9 around each branch limit, where
// a wrong branch formula or a wrong limit would show as a step.
std::vector<double> feed_grid(double rho, double phi1_deg) {
  std::vector<double> feeds;
  const int steps = 600;
  for (int i = 0; i <= steps; ++i) {
    feeds.push_back(1e-4 * std::pow(5e5, static_cast<double>(i) / steps));
  }
  if (phi1_deg > 0.0) {
    const auto limits = roughness_detail::branch_limits(
        rho, roughness_detail::minor_edge_angle(phi1_deg * kRadPerDeg));
    for (const double S_limit : {limits.S_AB, limits.S_BC}) {
      for (int j = -3; j <= 3; ++j) {
        feeds.push_back(S_limit * (1.0 + 1e-9 * j));
      }
    }
  }
  std::sort(feeds.begin(), feeds.end());
  return feeds;
}

// R7 over 6 radii x 16 angles x ~600 feeds: no decrease anywhere, strictly increasing for
// phi1 > 0, identically 0 for phi1 = 0.
TEST(GrooveWallProperty, CrestHeightNeverDecreasesWithTheFeed) {
  std::size_t points = 0;
  for (const double rho : kRhos) {
    for (const double phi1_deg : kAngles) {
      const std::vector<double> feeds = feed_grid(rho, phi1_deg);
      double previous = rz_mm(feeds.front(), rho, phi1_deg);
      for (std::size_t i = 1; i < feeds.size(); ++i) {
        const double current = rz_mm(feeds[i], rho, phi1_deg);
        ++points;
        if (phi1_deg == 0.0) {
          ASSERT_EQ(current, 0.0);
        } else {
          ASSERT_GT(current, previous) << "rho " << rho << " phi1 " << phi1_deg << " S "
                                       << feeds[i - 1] << " -> " << feeds[i];
        }
        previous = current;
      }
    }
  }
  EXPECT_GT(points, 50000U);
}

// R7: Rz grows without bound, so every target has a finite maximum feed.
TEST(GrooveWallProperty, CrestHeightGrowsWithoutBound) {
  for (const double phi1_deg : {0.01, 2.0, 45.0}) {
    EXPECT_GT(rz_mm(1e6, 0.3, phi1_deg), 100.0) << "phi1 " << phi1_deg;
  }
}

// Targets in every branch (including the limit values rho (1 - cos phi1) and rho themselves and
// values just beside them), for every radius and angle > 0.
std::vector<double> targets_um(double rho, double phi1_deg) {
  std::vector<double> targets;
  for (int i = 0; i <= 40; ++i) {
    targets.push_back(1e-3 * std::pow(1e8, i / 40.0));  // 1e-3 .. 1e5 um
  }
  const double T_AB = rho * (1.0 - std::cos(phi1_deg * kRadPerDeg));
  for (const double T_limit_mm : {T_AB, rho}) {
    for (const double factor : {1.0 - 1e-9, 1.0, 1.0 + 1e-9}) {
      targets.push_back(1000.0 * T_limit_mm * factor);
    }
  }
  return targets;
}

// R8: Rz(max_feed) = target to 1e-9 mm (in fact to a relative 1e-11), and any larger feed
// exceeds the target: max_feed_mm is the largest admissible feed, not merely an admissible one.
TEST(GrooveWallProperty, MaxFeedSolvesTheTargetExactly) {
  std::size_t cases = 0;
  for (const double rho : kRhos) {
    for (const double phi1_deg : kAngles) {
      if (phi1_deg == 0.0) {
        continue;
      }
      for (const double target_um : targets_um(rho, phi1_deg)) {
        const double T = target_um / 1000.0;
        const double S_max = max_feed_mm(rho, phi1_deg, target_um);
        ASSERT_GT(S_max, 0.0);
        const double at_max = rz_mm(S_max, rho, phi1_deg);
        EXPECT_NEAR(at_max, T, 1e-9) << "rho " << rho << " phi1 " << phi1_deg << " T " << T;
        EXPECT_NEAR(at_max, T, 1e-11 * T) << "rho " << rho << " phi1 " << phi1_deg << " T " << T;
        EXPECT_GT(rz_mm(S_max * (1.0 + 1e-8), rho, phi1_deg), T)
            << "rho " << rho << " phi1 " << phi1_deg << " T " << T;
        EXPECT_LT(rz_mm(S_max * (1.0 - 1e-8), rho, phi1_deg), T)
            << "rho " << rho << " phi1 " << phi1_deg << " T " << T;
        ++cases;
      }
    }
  }
  EXPECT_GT(cases, 3000U);
}

// R8 against bisection on the forward function (the spec's accepted alternative), to 1e-12.
TEST(GrooveWallProperty, MaxFeedAgreesWithBisectionOnTheCrestHeight) {
  for (const double rho : {0.1, 0.3, 1.2}) {
    for (const double phi1_deg : {0.5, 2.0, 10.0, 30.0, 60.0, 89.0}) {
      for (const double target_um : {0.01, 1.0, 13.2, 150.0, 400.0, 5000.0}) {
        const double T = target_um / 1000.0;
        double lo = 0.0;
        double hi = 1.0;
        while (rz_mm(hi, rho, phi1_deg) <= T) {
          hi *= 2.0;
        }
        for (int i = 0; i < 200; ++i) {
          const double mid = 0.5 * (lo + hi);
          if (mid == lo || mid == hi) {
            break;
          }
          (rz_mm(mid, rho, phi1_deg) <= T ? lo : hi) = mid;
        }
        const double S_max = max_feed_mm(rho, phi1_deg, target_um);
        EXPECT_NEAR(S_max, lo, 1e-12 * lo)
            << "rho " << rho << " phi1 " << phi1_deg << " target " << target_um;
      }
    }
  }
}

// R8 notes: max_feed_mm does not depend on feed_mm; rz_um and branch do.
TEST(GrooveWallProperty, MaxFeedDoesNotDependOnTheFeed) {
  const double reference = max_feed_mm(0.3, 10.0, 400.0, 0.2);
  for (const double feed : {1e-5, 0.08, 2.0, 50.0}) {
    EXPECT_EQ(max_feed_mm(0.3, 10.0, 400.0, feed), reference);
  }
  EXPECT_NEAR(reference, 2.5947593, 5e-8);  // branch C target of the reference cases
}

}  // namespace
