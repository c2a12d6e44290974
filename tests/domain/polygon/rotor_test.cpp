// The rotor of spec polygon-holes.md section 2 (P11-P13): flank radii, closure, widths, and the
// property that the rotor placed by P6-P7 touches all N sides and crosses none, with the support
// taken from the boundary pieces themselves (not from P13).

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "domain/polygon/centre_path.h"
#include "domain/polygon/fitted_arc.h"
#include "domain/polygon/polygon_geometry.h"
#include "domain/polygon/rotor.h"
#include "polygon_test_support.h"

namespace {

namespace polygon_detail = cutcalc::domain::polygon::detail;
using cutcalc::test::polygon::kPi;

// Angle x reduced to [0, 2 pi).
double wrap(double x) {
  x = std::fmod(x, 2.0 * kPi);
  return x < 0.0 ? x + 2.0 * kPi : x;
}

// The support of the rotor boundary in world direction `a` for the pose (centre c, angle phi),
// as the maximum over its pieces: every corner point, and every flank arc (its circle where `a`
// is inside its turned normal range, else its end points).
double support_from_pieces(const polygon_detail::Rotor& rotor,
                           const polygon_detail::PolygonShape& shape, const Eigen::Vector2d& c,
                           double phi, double a) {
  const Eigen::Rotation2Dd turn(phi);
  const Eigen::Vector2d n = polygon_detail::unit(a);
  double best = -std::numeric_limits<double>::infinity();
  for (int v = 0; v < shape.M; ++v) {
    best = std::max(best, (c + turn * rotor.corner(v)).dot(n));
    for (int m = 1; m <= shape.N - 2; ++m) {
      const polygon_detail::FlankArc arc = rotor.flank_arc(v, m);
      const Eigen::Vector2d O = c + turn * arc.centre;
      const double width = arc.normal_end - arc.normal_begin;
      if (wrap(a - (arc.normal_begin + phi)) <= width) {
        best = std::max(best, O.dot(n) + arc.radius);
      } else {
        best =
            std::max(best, (O + arc.radius * polygon_detail::unit(arc.normal_begin + phi)).dot(n));
        best = std::max(best, (O + arc.radius * polygon_detail::unit(arc.normal_end + phi)).dot(n));
      }
    }
  }
  return best;
}

TEST(RotorShape, FlankRadiiTable) {
  // Spec section 2: R_m / d, m = 1..N-2.
  const std::vector<std::vector<double>> table{
      {1.5},
      {1, 1},
      {0.690983, 1.118034, 0.690983},
      {0.5, 1, 1, 0.5},
      {0.376510, 0.846011, 1.054958, 0.846011, 0.376510},
      {0.292893, 0.707107, 1, 1, 0.707107, 0.292893},
  };
  for (int N = 3; N <= 8; ++N) {
    SCOPED_TRACE(N);
    const polygon_detail::Rotor rotor(polygon_detail::make_polygon_shape(N, 1.0));
    const std::vector<double>& row = table[static_cast<std::size_t>(N - 3)];
    for (int m = 1; m <= N - 2; ++m) {
      EXPECT_NEAR(rotor.flank_radius(m), row[static_cast<std::size_t>(m - 1)], 5e-7);
    }
  }
  for (int N = 3; N <= 12; ++N) {
    const polygon_detail::Rotor rotor(polygon_detail::make_polygon_shape(N, 1.0));
    for (int m = 1; m <= N - 2; ++m) {
      EXPECT_NEAR(rotor.flank_radius(m), rotor.flank_radius(N - 1 - m), 1e-15);  // R_m = R_{N-1-m}
    }
  }
}

// P12: consecutive arcs meet (tangent-continuous circles), the first starts at K_v and the last
// ends exactly at K_{v+1} (error < 1e-9 d).
TEST(RotorShape, BoundaryClosesExactly) {
  for (int N = 3; N <= 12; ++N) {
    SCOPED_TRACE(N);
    const double d = 20.0;
    const polygon_detail::PolygonShape shape = polygon_detail::make_polygon_shape(N, d);
    const polygon_detail::Rotor rotor(shape);
    for (int v = 0; v < shape.M; ++v) {
      const polygon_detail::FlankArc first = rotor.flank_arc(v, 1);
      EXPECT_NEAR(
          (first.centre + first.radius * polygon_detail::unit(first.normal_begin) - rotor.corner(v))
              .norm(),
          0.0, 1e-12 * d);
      for (int m = 1; m + 1 <= N - 2; ++m) {
        const polygon_detail::FlankArc a = rotor.flank_arc(v, m);
        const polygon_detail::FlankArc b = rotor.flank_arc(v, m + 1);
        EXPECT_NEAR(a.normal_end, b.normal_begin, 1e-15);
        EXPECT_NEAR((a.centre + a.radius * polygon_detail::unit(a.normal_end) -
                     (b.centre + b.radius * polygon_detail::unit(b.normal_begin)))
                        .norm(),
                    0.0, 1e-12 * d);
      }
      EXPECT_LT((rotor.last_arc_end(v) - rotor.corner((v + 1) % shape.M)).norm(), 1e-9 * d);
    }
  }
}

// P13 equals the support taken from the pieces, for any normal angle.
TEST(RotorShape, SupportFunctionMatchesTheBoundaryPieces) {
  std::mt19937 random(4);
  std::uniform_real_distribution<double> angle(-10.0, 10.0);
  for (int N = 3; N <= 12; ++N) {
    SCOPED_TRACE(N);
    const polygon_detail::PolygonShape shape = polygon_detail::make_polygon_shape(N, 20.0);
    const polygon_detail::Rotor rotor(shape);
    for (int k = 0; k < 400; ++k) {
      const double b = angle(random);
      EXPECT_NEAR(rotor.support(b),
                  support_from_pieces(rotor, shape, Eigen::Vector2d::Zero(), 0.0, b), 1e-12);
    }
  }
}

// Section 2 facts: constant width d for even N, width 2 min h .. 2r for odd N (section 12:
// 18.4430..21.5246 for N = 5, 19.3853..20.6114 for N = 7, 8.0385..30 for N = 3 at d = 20),
// Reuleaux triangle for N = 4 (R = d), lens for N = 3 (R = 1.5 d, 60 deg point angle).
TEST(RotorShape, WidthsAndSpecialCases) {
  const double d = 20.0;
  for (int N = 3; N <= 12; ++N) {
    SCOPED_TRACE(N);
    const polygon_detail::PolygonShape shape = polygon_detail::make_polygon_shape(N, d);
    const polygon_detail::Rotor rotor(shape);
    double min_width = std::numeric_limits<double>::infinity();
    double max_width = 0.0;
    for (int k = 0; k < 20000; ++k) {
      const double b = 2.0 * kPi * k / 20000.0;
      const double width = rotor.support(b) + rotor.support(b + kPi);
      min_width = std::min(min_width, width);
      max_width = std::max(max_width, width);
    }
    if (N % 2 == 0) {
      EXPECT_NEAR(min_width, d, 1e-12);
      EXPECT_NEAR(max_width, d, 1e-12);
    } else {
      EXPECT_LE(max_width, 2.0 * shape.r + 1e-12);
    }
    if (N == 3) {
      EXPECT_NEAR(min_width, 8.0385, 1e-4);
      EXPECT_NEAR(max_width, 30.0, 1e-4);
    } else if (N == 5) {
      EXPECT_NEAR(min_width, 18.4430, 1e-4);
      EXPECT_NEAR(max_width, 21.5246, 1e-4);
    } else if (N == 7) {
      EXPECT_NEAR(min_width, 19.3853, 1e-4);
      EXPECT_NEAR(max_width, 20.6114, 1e-4);
    }
  }
  EXPECT_NEAR(polygon_detail::Rotor(polygon_detail::make_polygon_shape(4, d)).flank_radius(1), d,
              1e-12);
  EXPECT_NEAR(polygon_detail::Rotor(polygon_detail::make_polygon_shape(3, d)).flank_radius(1),
              1.5 * d, 1e-12);
}

// The property of section 2: placed by P6-P7 (centre c(t), angle phi = -t) at any phase, the
// rotor touches all N sides (max over its boundary of <x, u_j> = rho to 1e-9 mm) and crosses none.
TEST(RotorContact, TouchesAllSidesAtEveryPhase) {
  std::mt19937 random(11);
  for (int N = 3; N <= 12; ++N) {
    for (double d : {1.0, 250.0}) {
      SCOPED_TRACE(testing::Message() << "N " << N << " d " << d);
      const polygon_detail::PolygonShape shape = polygon_detail::make_polygon_shape(N, d);
      const polygon_detail::CentrePath path(shape);
      const polygon_detail::Rotor rotor(shape);
      const double loop = N * shape.delta;
      std::uniform_real_distribution<double> phase(0.0, 3.0 * loop);
      std::vector<double> instants;
      for (int k = 0; k <= 4 * N; ++k) {
        instants.push_back(0.5 * k * shape.delta);  // phase changes and mid-phases
      }
      for (int k = 0; k < 80; ++k) {
        instants.push_back(phase(random));
      }
      double worst_gap = 0.0;
      double worst_crossing = 0.0;
      for (const double t : instants) {
        const Eigen::Vector2d c = path.point(t);
        for (int j = 0; j < N; ++j) {
          const double gap = shape.rho - support_from_pieces(rotor, shape, c, -t, shape.alpha(j));
          worst_gap = std::max(worst_gap, std::abs(gap));
          worst_crossing = std::max(worst_crossing, -gap);
        }
      }
      EXPECT_LE(worst_gap, 1e-9);
      EXPECT_LE(worst_crossing, 1e-9);
    }
  }
}

// A wrong phase makes the rotor cross a side: the contact property is not vacuous.
TEST(RotorContact, AWrongPhaseCrossesASide) {
  for (int N = 3; N <= 12; ++N) {
    const polygon_detail::PolygonShape shape = polygon_detail::make_polygon_shape(N, 20.0);
    const polygon_detail::CentrePath path(shape);
    const polygon_detail::Rotor rotor(shape);
    const double t = 0.3 * shape.delta;
    double crossing = -std::numeric_limits<double>::infinity();
    for (int j = 0; j < N; ++j) {
      crossing = std::max(
          crossing,
          support_from_pieces(rotor, shape, path.point(t), -t + 0.01, shape.alpha(j)) - shape.rho);
    }
    EXPECT_GT(crossing, 1e-4) << N;
  }
}

}  // namespace
