// Shape constants of spec polygon-holes.md section 4 (P1-P5, P7, P9, P10, P15, P16, P17) for
// N = 3..12, the reference table of section 12, and the centre path (P6-P10) checked against its
// defining conditions.

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "domain/polygon/centre_path.h"
#include "domain/polygon/hole_prediction.h"
#include "domain/polygon/polygon_geometry.h"
#include "polygon_test_support.h"

namespace {

namespace polygon_detail = cutcalc::domain::polygon::detail;
using cutcalc::test::polygon::kPi;

// A value printed with 10 significant digits: half a unit in the last digit, relative.
double ten_digits(double value) { return 6e-10 * std::abs(value) + 1e-13; }

struct ShapeRow {
  int N;
  double q, e, r, A, B, r_max, L, g, rho_c, kappa_A;  // lengths / d
};

// Spec section 4 table.
constexpr std::array<ShapeRow, 10> kShapeTable{{
    {3, 0.3333333333, 0.25, 0.75, 1.299038106, 0.4330127019, 0.2990381057, 1.742300182, 0, 0, 0},
    {4, 0.1339745962, 0.07735026919, 0.5773502692, 0.7886751346, 0.2113248654, 0.08156835341,
     0.5005253036, 0.04818815859, 0.09807621135, 0.01229960926},
    {5, 0.07083167503, 0.03811563154, 0.5381156315, 0.6569584309, 0.1432152825, 0.03892444211,
     0.2422467945, 0.04180272567, 0.1226186376, 0.01712724268},
    {6, 0.04370479853, 0.02285110208, 0.5228511021, 0.6004291176, 0.1093056444, 0.02307884843,
     0.1443506051, 0.03142031868, 0.1522503847, 0.01546390230},
    {7, 0.02966499667, 0.01528595618, 0.5152859562, 0.5703250472, 0.08875042841, 0.01536691513,
     0.09631834913, 0.02438621974, 0.1687757866, 0.01260542332},
    {8, 0.02146785826, 0.01096941906, 0.5109694191, 0.5521992334, 0.07486679963, 0.01100313330,
     0.06903668974, 0.01922354779, 0.1788855364, 0.01042766924},
    {9, 0.01626506316, 0.008266994770, 0.5082669948, 0.5403716343, 0.06482160587, 0.008282748041,
     0.05199615332, 0.01555489670, 0.1898896138, 0.008707233905},
    {10, 0.01275479843, 0.006459792567, 0.5064597926, 0.5321989411, 0.05719812238, 0.006467829030,
     0.04061512987, 0.01280349052, 0.1943237386, 0.007351040065},
    {11, 0.01027358972, 0.005190115984, 0.5051901160, 0.5263030681, 0.05120542253, 0.005194509985,
     0.03262524181, 0.01072832614, 0.2020661500, 0.006256762664},
    {12, 0.008454295434, 0.004263189984, 0.5042631900, 0.5219038214, 0.04636560990, 0.004265731240,
     0.02679495617, 0.009109168980, 0.2043236544, 0.005388589461},
}};

TEST(PolygonShape, SectionFourTableForEveryN) {
  for (const ShapeRow& row : kShapeTable) {
    SCOPED_TRACE(row.N);
    const polygon_detail::PolygonShape shape = polygon_detail::make_polygon_shape(row.N, 1.0);
    const polygon_detail::CentrePath path(shape);
    EXPECT_NEAR(shape.q, row.q, ten_digits(row.q));
    EXPECT_NEAR(shape.e, row.e, ten_digits(row.e));
    EXPECT_NEAR(shape.r, row.r, ten_digits(row.r));
    EXPECT_NEAR(shape.A, row.A, ten_digits(row.A));
    EXPECT_NEAR(shape.B, row.B, ten_digits(row.B));
    EXPECT_NEAR(shape.r_max, row.r_max, ten_digits(row.r_max));
    EXPECT_NEAR(path.loop_length(), row.L, ten_digits(row.L));
    EXPECT_NEAR(polygon_detail::corner_gap(shape), row.g, ten_digits(row.g));
    EXPECT_NEAR(polygon_detail::corner_wall_min_radius(path), row.rho_c, ten_digits(row.rho_c));
    EXPECT_NEAR(polygon_detail::uncut_area_coefficient(row.N), row.kappa_A,
                ten_digits(row.kappa_A));
  }
}

TEST(PolygonShape, ClosedFormsOfTheSquare) {
  const polygon_detail::PolygonShape shape =
      polygon_detail::make_polygon_shape(4, 2.0);  // square of side 2
  EXPECT_NEAR(shape.A, 1.0 + 1.0 / std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(shape.B, 1.0 - 1.0 / std::sqrt(3.0), 1e-15);
  const polygon_detail::CentrePath path(shape);
  // P16: rho_c = (r - B)^2 / (A + r) for even N; (2 - sqrt3) / (1 + sqrt3) a for the square.
  EXPECT_NEAR(polygon_detail::corner_wall_min_radius(path),
              (shape.r - shape.B) * (shape.r - shape.B) / (shape.A + shape.r), 1e-14);
  EXPECT_NEAR(polygon_detail::corner_wall_min_radius(path),
              (2.0 - std::sqrt(3.0)) / (1.0 + std::sqrt(3.0)) * shape.a, 1e-14);
  // P17: the classical Reuleaux-drill result.
  EXPECT_NEAR(polygon_detail::uncut_area_coefficient(4), 4.0 - 2.0 * std::sqrt(3.0) - kPi / 6.0,
              1e-15);
  EXPECT_NEAR(polygon_detail::uncut_area_coefficient(4), 0.01229960926, 5e-12);
}

// P17 by Green's theorem for N = 4 and 5, where the corner wall is exactly the path X of rotor
// corner 1 (P14) over its free phases t in [2 delta, (N-1) delta]: an independent check of the
// tabulated kappa_A.
TEST(PolygonShape, UncutAreaFromTheCornerPathForNFourAndFive) {
  for (int N : {4, 5}) {
    SCOPED_TRACE(N);
    const polygon_detail::PolygonShape shape = polygon_detail::make_polygon_shape(N, 1.0);
    const polygon_detail::CentrePath path(shape);
    const double t0 = 2.0 * shape.delta;
    const double t1 = (N - 1.0) * shape.delta;
    const Eigen::Vector2d V0 = shape.vertex(0);
    // Closed boundary (counter-clockwise is irrelevant: the absolute value is taken): V0 ->
    // X(t1) on side 0 -> wall backwards to X(t0) on side 1 -> V0.
    auto edge = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
      return 0.5 * (a.x() * b.y() - a.y() * b.x());
    };
    double area = edge(V0, polygon_detail::corner_path(path, t1)) +
                  edge(polygon_detail::corner_path(path, t0), V0);
    constexpr int n = 20000;  // Simpson on the wall
    const double h = (t0 - t1) / n;
    double integral = 0.0;
    for (int k = 0; k <= n; ++k) {
      const double t = t1 + k * h;
      const Eigen::Vector2d X = polygon_detail::corner_path(path, t);
      const double theta_1 = -0.5 * kPi + 2.0 * kPi / shape.M;
      const Eigen::Vector2d dX =
          path.velocity(t) - shape.r * polygon_detail::unit(theta_1 - t + 0.5 * kPi);
      const double f = 0.5 * (X.x() * dX.y() - X.y() * dX.x());
      integral += f * (k == 0 || k == n ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0));
    }
    area += integral * h / 3.0;
    EXPECT_NEAR(N * std::abs(area), polygon_detail::uncut_area_coefficient(N), 1e-10);
  }
}

// P15 against P14: the corner path crosses the vertex bisector at t* at distance g from V_0.
TEST(PolygonShape, CornerGapIsTheCornerPathOnTheBisector) {
  for (int N = 4; N <= 12; ++N) {
    SCOPED_TRACE(N);
    const polygon_detail::PolygonShape shape = polygon_detail::make_polygon_shape(N, 1.0);
    const polygon_detail::CentrePath path(shape);
    const double t_star = 0.5 * (N + 1.0) * shape.delta;
    const Eigen::Vector2d X = polygon_detail::corner_path(path, t_star);
    EXPECT_NEAR((shape.vertex(0) - X).norm(), polygon_detail::corner_gap(shape), 1e-13);
    EXPECT_NEAR(polygon_detail::cross(shape.vertex(0).normalized(), X), 0.0, 1e-13);
  }
}

// Section 12 (d = 20 for N = 3..8 and the square a = 16): e, span 2r, L exact, uncut total,
// corner gap, rho_c, blocks per loop and F limit at 1 um and 2 ms.
TEST(PolygonShape, SectionTwelveReferenceNumbers) {
  struct Row {
    int N;
    double d, e, span, L, uncut, gap, rho_c;
    int blocks;
    double f_limit;
  };
  constexpr std::array<Row, 7> rows{{
      {3, 20, 5.000000, 30.0000, 34.846004, 0, 0, 0, 43, 17390},
      {4, 20, 1.547005, 23.0940, 10.010506, 4.919844, 0.963763, 1.961524, 25, 8601},
      {5, 20, 0.762313, 21.5246, 4.844936, 6.850897, 0.836055, 2.452373, 11, 7290},
      {6, 20, 0.457022, 20.9140, 2.887012, 6.185561, 0.628406, 3.045008, 13, 3614},
      {7, 20, 0.305719, 20.6114, 1.926367, 5.042169, 0.487724, 3.375516, 15, 2066},
      {8, 20, 0.219388, 20.4388, 1.380734, 4.171068, 0.384471, 3.577711, 1, 41354},
      {4, 16, 1.237604, 18.4752, 8.008405, 3.148700, 0.771011, 1.569219, 25, 6881},
  }};
  for (const Row& row : rows) {
    SCOPED_TRACE(testing::Message() << "N " << row.N << " d " << row.d);
    const polygon_detail::PolygonShape shape = polygon_detail::make_polygon_shape(row.N, row.d);
    const polygon_detail::CentrePath path(shape);
    EXPECT_NEAR(shape.e, row.e, 5e-7);
    EXPECT_NEAR(2.0 * shape.r, row.span, 5e-5);
    EXPECT_NEAR(path.loop_length(), row.L, 5e-7);
    EXPECT_NEAR(polygon_detail::corner_wall_min_radius(path), row.rho_c, 5e-7);
    const auto result =
        cutcalc::test::polygon::generate(cutcalc::test::polygon::hole(row.N, row.d));
    EXPECT_NEAR(result.uncut_corner_area_mm2, row.uncut, 5e-7);
    EXPECT_NEAR(result.corner_gap_mm, row.gap, 5e-7);
    EXPECT_EQ(result.blocks_per_loop, row.blocks);
    EXPECT_NEAR(result.max_feed_by_block_rate_mm_per_min, row.f_limit, 0.5);
  }
}

// P6: in phase p, <c, u_p> = rho - r cos(theta) and <c, u_{p+1}> = rho - r cos(delta - theta).
TEST(CentrePath, LadderConditionsOfEveryPhase) {
  for (int N = 3; N <= 12; ++N) {
    SCOPED_TRACE(N);
    const polygon_detail::PolygonShape shape = polygon_detail::make_polygon_shape(N, 20.0);
    const polygon_detail::CentrePath path(shape);
    for (int k = 0; k <= 997; ++k) {
      const double t = k * N * shape.delta / 997.0;
      const int p = std::min(static_cast<int>(t / shape.delta), N - 1);
      const double theta = t - p * shape.delta;
      const Eigen::Vector2d c = path.point_in_phase(p, theta);
      EXPECT_NEAR(c.dot(shape.u(p)), shape.rho - shape.r * std::cos(theta), 1e-12);
      EXPECT_NEAR(c.dot(shape.u((p + 1) % N)), shape.rho - shape.r * std::cos(shape.delta - theta),
                  1e-12);
    }
  }
}

// P7-P9: start (0, e), |c| = e at phase changes and r_max at mid-phase, C1 at the joins, and
// c', c'' the derivatives of c.
TEST(CentrePath, ExtremesJoinsAndDerivatives) {
  for (int N = 3; N <= 12; ++N) {
    SCOPED_TRACE(N);
    const polygon_detail::PolygonShape shape = polygon_detail::make_polygon_shape(N, 20.0);
    const polygon_detail::CentrePath path(shape);
    EXPECT_NEAR(path.point(0.0).x(), 0.0, 1e-14);
    EXPECT_NEAR(path.point(0.0).y(), shape.e, 1e-14);
    for (int p = 0; p < N; ++p) {
      EXPECT_NEAR(path.point_in_phase(p, 0.0).norm(), shape.e, 1e-13);
      EXPECT_NEAR(path.point_in_phase(p, 0.5 * shape.delta).norm(), shape.r_max, 1e-13);
      // C1 join: the end of phase p equals the start of phase p + 1, with the same tangent.
      const Eigen::Vector2d end = path.point_in_phase(p, shape.delta);
      const Eigen::Vector2d start = path.point_in_phase(p + 1, 0.0);
      EXPECT_NEAR((end - start).norm(), 0.0, 1e-13);
      const Eigen::Vector2d v_end = path.velocity_in_phase(p, shape.delta);
      const Eigen::Vector2d v_start = path.velocity_in_phase(p + 1, 0.0);
      EXPECT_NEAR((v_end - v_start).norm(), 0.0, 1e-12);
      // Counter-clockwise: c x c' > 0.
      EXPECT_GT(polygon_detail::cross(start, v_start), 0.0);
    }
    const double h = 1e-6;
    for (double t : {0.1 * shape.delta, 1.37 * shape.delta, 2.9 * shape.delta}) {
      const Eigen::Vector2d numeric_v = (path.point(t + h) - path.point(t - h)) / (2.0 * h);
      const Eigen::Vector2d numeric_a = (path.velocity(t + h) - path.velocity(t - h)) / (2.0 * h);
      EXPECT_NEAR((numeric_v - path.velocity(t)).norm(), 0.0, 1e-7 * shape.d);
      EXPECT_NEAR((numeric_a - path.acceleration(t)).norm(), 0.0, 1e-7 * shape.d);
    }
  }
}

// P10: the 40-point Gauss-Legendre length against a fine composite Simpson sum of |c'|.
TEST(CentrePath, LoopLengthMatchesAFineQuadrature) {
  for (int N = 3; N <= 12; ++N) {
    SCOPED_TRACE(N);
    const polygon_detail::PolygonShape shape = polygon_detail::make_polygon_shape(N, 1.0);
    const polygon_detail::CentrePath path(shape);
    constexpr int n = 20000;
    const double h = shape.delta / n;
    double sum = 0.0;
    for (int k = 0; k <= n; ++k) {
      const double speed = path.velocity_in_phase(0, k * h).norm();
      sum += speed * (k == 0 || k == n ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0));
    }
    EXPECT_NEAR(path.loop_length(), N * sum * h / 3.0, 1e-13);
  }
}

}  // namespace
