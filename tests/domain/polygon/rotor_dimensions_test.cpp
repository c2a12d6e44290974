// The rotor's dimensions of spec polygon-holes.md section 13 (P28-P31): the paper's square and the
// d = 20 rotors of the section's table, the widths and the neck against a sampled support
// function, and the corner radius at the odd-N phase join.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "domain/polygon/centre_path.h"
#include "domain/polygon/hole_prediction.h"
#include "domain/polygon/polygon_geometry.h"
#include "domain/polygon/polygon_hole.h"
#include "domain/polygon/rotor.h"
#include "domain/polygon/rotor_dimensions.h"
#include "polygon_test_support.h"

namespace {

namespace polygon_detail = cutcalc::domain::polygon::detail;
using cutcalc::domain::polygon::RotorDimensions;
using cutcalc::test::polygon::kPi;

RotorDimensions dimensions(int N, double d) {
  return polygon_detail::rotor_dimensions(polygon_detail::make_polygon_shape(N, d));
}

// P28: the paper's square a = 16 (d = 16): 3 corners on 18.4752, 120 deg, R1 = R2 = d, both
// about the opposite corner.
TEST(RotorDimensions, SquareHasThreeCornersOnTheGrindingDiameterAndArcsOfRadiusD) {
  const RotorDimensions rotor = dimensions(4, 16.0);
  EXPECT_EQ(rotor.corners, 3);
  EXPECT_NEAR(rotor.corner_circle_diameter_mm, 18.4752, 1e-4);
  EXPECT_NEAR(rotor.corner_angle_deg, 120.0, 1e-12);
  ASSERT_EQ(rotor.flank_arcs.size(), 2U);
  for (const auto& arc : rotor.flank_arcs) {
    EXPECT_NEAR(arc.radius_mm, 16.0, 1e-12);
    // The centre of the flank between corners 0 and 1 is the third corner, K_2 = r n(150 deg).
    EXPECT_NEAR(arc.centre_x_mm, 0.5 * 18.4752 * std::cos(150.0 * kPi / 180.0), 1e-4);
    EXPECT_NEAR(arc.centre_y_mm, 0.5 * 18.4752 * std::sin(150.0 * kPi / 180.0), 1e-4);
  }
  EXPECT_NEAR(rotor.flank_arcs[0].start_angle_deg, -60.0, 1e-12);
  EXPECT_NEAR(rotor.flank_arcs[0].end_angle_deg, -30.0, 1e-12);
  EXPECT_NEAR(rotor.flank_arcs[1].start_angle_deg, -30.0, 1e-12);
  EXPECT_NEAR(rotor.flank_arcs[1].end_angle_deg, 0.0, 1e-12);
}

// P28: the included corner angle is 180 - 2 delta, delta = 360 / (N (N - 1)) deg.
TEST(RotorDimensions, CornerAngleIsTheSupplementOfTheNormalCone) {
  for (int N = 3; N <= 12; ++N) {
    const RotorDimensions rotor = dimensions(N, 20.0);
    EXPECT_EQ(rotor.corners, N - 1);
    EXPECT_NEAR(rotor.corner_angle_deg, 180.0 - 720.0 / (N * (N - 1.0)), 1e-9) << N;
    EXPECT_EQ(rotor.flank_arcs.size(), static_cast<std::size_t>(N - 2)) << N;
  }
}

// Section 13's table, d = 20: 2r and the largest neck for N = 4..8 (3 decimals).
TEST(RotorDimensions, PaperToolAgainstTheExactRotorForDiameter20) {
  constexpr std::array<double, 5> corner_circle{23.094, 21.525, 20.914, 20.611, 20.439};
  constexpr std::array<double, 5> neck{16.906, 18.443, 19.086, 19.385, 19.561};
  for (int N = 4; N <= 8; ++N) {
    const RotorDimensions rotor = dimensions(N, 20.0);
    EXPECT_NEAR(rotor.corner_circle_diameter_mm, corner_circle[N - 4], 5e-4) << N;
    EXPECT_NEAR(rotor.neck_diameter_max_mm, neck[N - 4], 5e-4) << N;
    // The paper's D = 0.76 d clears as a neck, below every bound.
    EXPECT_LT(0.76 * 20.0, rotor.neck_diameter_max_mm) << N;
  }
}

// P29, P30 against a second method: h(b) + h(b + pi) and h(b) sampled over 20 001 directions.
TEST(RotorDimensions, WidthsAndNeckAgreeWithTheSampledSupportFunction) {
  for (int N = 3; N <= 12; ++N) {
    const double d = 20.0;
    const auto shape = polygon_detail::make_polygon_shape(N, d);
    const polygon_detail::Rotor rotor(shape);
    double width_min = std::numeric_limits<double>::infinity();
    double width_max = 0.0;
    double h_min = std::numeric_limits<double>::infinity();
    constexpr int kSamples = 20001;
    for (int k = 0; k < kSamples; ++k) {
      const double b = 2.0 * kPi * k / (kSamples - 1);
      const double width = rotor.support(b) + rotor.support(b + kPi);
      width_min = std::min(width_min, width);
      width_max = std::max(width_max, width);
      h_min = std::min(h_min, rotor.support(b));
    }
    const RotorDimensions dims = polygon_detail::rotor_dimensions(shape);
    EXPECT_NEAR(dims.width_min_mm, width_min, 1e-6 * d) << N;
    EXPECT_NEAR(dims.width_max_mm, width_max, 1e-6 * d) << N;
    EXPECT_NEAR(dims.neck_diameter_max_mm, 2.0 * h_min, 1e-6 * d) << N;
    if (N % 2 == 0) {
      EXPECT_DOUBLE_EQ(dims.width_min_mm, d) << N;  // constant width
      EXPECT_DOUBLE_EQ(dims.width_max_mm, d) << N;
    }
  }
}

// P31 = P16: the square a = 16 has rho_c = 1.5692 mm; the triangle's corners stay sharp.
TEST(RotorDimensions, CornerRadiusOfTheSquareAndTheTriangle) {
  const auto square = polygon_detail::make_polygon_shape(4, 1.0);
  EXPECT_NEAR(polygon_detail::corner_wall_min_radius(polygon_detail::CentrePath(square)) * 16.0,
              1.5692, 1e-4);
  const auto triangle = polygon_detail::make_polygon_shape(3, 1.0);
  EXPECT_EQ(polygon_detail::corner_wall_min_radius(polygon_detail::CentrePath(triangle)), 0.0);
}

// P31, odd N: t* is a phase join; the phase that ends there and the one that starts there give
// the same radius (mirror symmetry), so the value does not hang on floor(t* / delta).
TEST(RotorDimensions, OddCornerRadiusIsTheSameFromEitherPhaseAtTheJoin) {
  for (int N = 5; N <= 11; N += 2) {
    const auto shape = polygon_detail::make_polygon_shape(N, 1.0);
    const polygon_detail::CentrePath path(shape);
    const double theta_1 = -0.5 * kPi + 2.0 * kPi / shape.M;
    const double t_star = 0.5 * (N + 1.0) * shape.delta;
    const auto radius_in_phase = [&](int p) {
      const double theta = t_star - p * shape.delta;
      const Eigen::Vector2d X1 = path.velocity_in_phase(p, theta) -
                                 shape.r * polygon_detail::unit(theta_1 - t_star + 0.5 * kPi);
      const Eigen::Vector2d X2 =
          path.acceleration_in_phase(p, theta) - shape.r * polygon_detail::unit(theta_1 - t_star);
      const double speed = X1.norm();
      return speed * speed * speed / std::abs(X1.x() * X2.y() - X1.y() * X2.x());
    };
    const double ending = radius_in_phase((N + 1) / 2 - 1);
    const double starting = radius_in_phase((N + 1) / 2);
    EXPECT_NEAR(ending, starting, 1e-9) << N;
    EXPECT_NEAR(polygon_detail::corner_wall_min_radius(path), ending, 1e-12) << N;
  }
}

}  // namespace
