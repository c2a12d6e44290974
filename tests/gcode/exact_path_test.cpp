// The tests' own exact centre path (spec polygon-holes.md P1-P10) against the spec's table of
// section 4 and against the contact conditions P6 it is derived from.

#include "gcode/exact_path.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using cutcalc::test::gcode::ExactCentrePath;
using cutcalc::test::gcode::Vec2;

struct TableRow {
  int faces;
  double q, e, r, a_axis, b_axis, r_max, loop_length;  // lengths / d
};

// Spec section 4, 10 significant digits.
constexpr TableRow kTable[] = {
    {3, 0.3333333333, 0.25, 0.75, 1.299038106, 0.4330127019, 0.2990381057, 1.742300182},
    {4, 0.1339745962, 0.07735026919, 0.5773502692, 0.7886751346, 0.2113248654, 0.08156835341,
     0.5005253036},
    {5, 0.07083167503, 0.03811563154, 0.5381156315, 0.6569584309, 0.1432152825, 0.03892444211,
     0.2422467945},
    {6, 0.04370479853, 0.02285110208, 0.5228511021, 0.6004291176, 0.1093056444, 0.02307884843,
     0.1443506051},
    {7, 0.02966499667, 0.01528595618, 0.5152859562, 0.5703250472, 0.08875042841, 0.01536691513,
     0.09631834913},
    {8, 0.02146785826, 0.01096941906, 0.5109694191, 0.5521992334, 0.07486679963, 0.01100313330,
     0.06903668974},
    {9, 0.01626506316, 0.008266994770, 0.5082669948, 0.5403716343, 0.06482160587, 0.008282748041,
     0.05199615332},
    {10, 0.01275479843, 0.006459792567, 0.5064597926, 0.5321989411, 0.05719812238, 0.006467829030,
     0.04061512987},
    {11, 0.01027358972, 0.005190115984, 0.5051901160, 0.5263030681, 0.05120542253, 0.005194509985,
     0.03262524181},
    {12, 0.008454295434, 0.004263189984, 0.5042631900, 0.5219038214, 0.04636560990, 0.004265731240,
     0.02679495617},
};

void expect_close(double actual, double expected, const char* what, int faces) {
  EXPECT_NEAR(actual, expected, 6e-10 * std::abs(expected) + 1e-12) << what << " N=" << faces;
}

TEST(ExactCentrePath, MatchesTheSpecTableForEveryN) {
  for (const auto& row : kTable) {
    const ExactCentrePath path(row.faces, 1.0);
    expect_close(path.q(), row.q, "q", row.faces);
    expect_close(path.e(), row.e, "e", row.faces);
    expect_close(path.r(), row.r, "r", row.faces);
    expect_close(path.semi_axis_a(), row.a_axis, "A", row.faces);
    expect_close(path.semi_axis_b(), row.b_axis, "B", row.faces);
    expect_close(path.r_max(), row.r_max, "r_max", row.faces);
    expect_close(path.loop_length(), row.loop_length, "L", row.faces);
  }
}

TEST(ExactCentrePath, ScalesWithTheDiameterAndMatchesSection12) {
  const ExactCentrePath square(4, 16.0);  // the paper's square a = 16
  EXPECT_NEAR(square.side(), 16.0, 1e-12);
  EXPECT_NEAR(square.e(), 1.237604, 5e-7);
  EXPECT_NEAR(square.loop_length(), 8.008405, 5e-7);
  const ExactCentrePath hexagon(6, 20.0);
  EXPECT_NEAR(hexagon.e(), 0.457022, 5e-7);
  EXPECT_NEAR(hexagon.loop_length(), 2.887012, 5e-7);
  EXPECT_NEAR(2.0 * hexagon.r(), 20.9140, 5e-5);
}

// P7 solves P6: in phase p corners p and p+1 touch sides p and p+1.
TEST(ExactCentrePath, SatisfiesTheContactConditionsP6) {
  for (int faces = 3; faces <= 12; ++faces) {
    const ExactCentrePath path(faces, 20.0);
    for (int p = 0; p < faces; ++p) {
      const Vec2 u_p = cutcalc::test::gcode::unit_at(-std::numbers::pi / 2.0 +
                                                     2.0 * std::numbers::pi * p / faces);
      const Vec2 u_next = cutcalc::test::gcode::unit_at(-std::numbers::pi / 2.0 +
                                                        2.0 * std::numbers::pi * (p + 1) / faces);
      for (int k = 0; k < 10; ++k) {
        const double theta = path.delta() * (k + 0.5) / 10.0;
        const Vec2 c = path.point(p * path.delta() + theta);
        EXPECT_NEAR(dot(c, u_p), path.rho() - path.r() * std::cos(theta), 1e-12)
            << "N=" << faces << " p=" << p;
        EXPECT_NEAR(dot(c, u_next), path.rho() - path.r() * std::cos(path.delta() - theta), 1e-12)
            << "N=" << faces << " p=" << p;
      }
    }
  }
}

TEST(ExactCentrePath, IsClosedTangentContinuousAndBetweenEAndRmax) {
  for (int faces = 3; faces <= 12; ++faces) {
    const ExactCentrePath path(faces, 20.0);
    const Vec2 start = path.point(0.0);
    EXPECT_NEAR(start.x, 0.0, 1e-12);
    EXPECT_NEAR(start.y, path.e(), 1e-12);  // P9 / section 3: c(0) = (0, e)
    const double eps = 1e-9;
    for (int p = 0; p <= faces; ++p) {
      const double t = p * path.delta();
      const Vec2 jump = path.point(t + eps) - path.point(t - eps);
      EXPECT_LT(norm(jump), 2.0 * eps * norm(path.derivative(t)) * (1.0 + 1e-3) + 1e-15);
      const double kink = std::abs(cutcalc::test::gcode::angle_between(path.unit_tangent(t - eps),
                                                                       path.unit_tangent(t + eps)));
      EXPECT_LT(kink, 1e-6) << "N=" << faces << " p=" << p;
      EXPECT_NEAR(norm(path.point(t)), path.e(), 1e-12);                           // phase change
      EXPECT_NEAR(norm(path.point(t + path.delta() / 2.0)), path.r_max(), 1e-12);  // mid-phase
    }
    double smallest = 1e9;
    double largest = 0.0;
    for (int k = 0; k < 10000; ++k) {
      const double radius = norm(path.point(path.loop_parameter() * k / 10000.0));
      smallest = std::min(smallest, radius);
      largest = std::max(largest, radius);
    }
    EXPECT_NEAR(smallest, path.e(), 1e-12);
    EXPECT_NEAR(largest, path.r_max(), 1e-12);
  }
}

TEST(ExactCentrePath, DerivativeMatchesFiniteDifferences) {
  const ExactCentrePath path(5, 20.0);
  for (int k = 1; k < 50; ++k) {
    const double t = path.loop_parameter() * (k + 0.37) / 50.0;
    const double h = 1e-6;
    const Vec2 numeric = (1.0 / (2.0 * h)) * (path.point(t + h) - path.point(t - h));
    EXPECT_NEAR(numeric.x, path.derivative(t).x, 1e-7);
    EXPECT_NEAR(numeric.y, path.derivative(t).y, 1e-7);
  }
}

TEST(ExactCentrePath, RunsCounterClockwise) {
  for (int faces = 3; faces <= 12; ++faces) {
    const ExactCentrePath path(faces, 20.0);
    for (int k = 0; k < 100; ++k) {
      const double t = path.loop_parameter() * k / 100.0;
      EXPECT_GT(cross(path.point(t), path.derivative(t)), 0.0);
    }
  }
}

// Points moved off the path along its normal are found at that distance, with their parameter.
TEST(ExactCentrePath, NearestPointRecoversOffsetsAlongTheNormal) {
  for (int faces : {3, 4, 7, 12}) {
    for (double d : {7.0, 20.0}) {
      const ExactCentrePath path(faces, d);
      for (int k = 0; k < 97; ++k) {
        const double t = path.loop_parameter() * (k + 0.123) / 97.0;
        const Vec2 normal = cutcalc::test::gcode::left_normal(path.unit_tangent(t));
        for (double offset : {-0.005, -0.0011, 0.0, 0.0011, 0.005}) {
          const auto nearest = path.nearest(path.point(t) + offset * normal);
          EXPECT_NEAR(nearest.distance, std::abs(offset), 1e-10)
              << "N=" << faces << " d=" << d << " t=" << t;
          EXPECT_NEAR(nearest.t, t, 1e-7) << "N=" << faces << " d=" << d;
        }
      }
    }
  }
}

}  // namespace
