// The arc fit and the printed-path deviation are computed with shortcuts (a search for failing
// biarcs, bounds that skip samples, expansions that settle comparisons) that must give the same
// numbers to the last bit as their literal definitions: spec polygon-holes.md P18-P21 and
// programs.md section 4. Each test here writes the definition out and compares with ==.

#include <gtest/gtest.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "domain/common/golden_section.h"
#include "domain/polygon/biarc_fit.h"
#include "domain/polygon/centre_path.h"
#include "domain/polygon/gcode_writer.h"
#include "domain/polygon/polygon_geometry.h"
#include "domain/polygon/printed_deviation.h"

namespace {

namespace fit_detail = cutcalc::domain::polygon::detail;

// P21 literally: m = 1, 2, ... with biarcs 0 .. (m + 1) / 2 - 1 in order, each within the
// tolerance, the first m where all are. Returns m and the largest deviation (0 when none fits).
struct LiteralFit {
  int m = 0;
  double deviation = 0.0;
};

LiteralFit literal_smallest_m(const fit_detail::CentrePath& path, double tolerance, int max_m) {
  const fit_detail::PolygonShape& shape = path.shape();
  auto knot = [&](int m, int i) {
    const double theta = i * shape.delta / m;
    Eigen::Vector2d P = path.point_in_phase(0, theta);
    if (i == 0) {
      P = Eigen::Vector2d(0.0, shape.e);
    } else if (i == m) {
      P = -shape.e * shape.u(1);
    }
    return std::pair{P, Eigen::Vector2d(path.velocity_in_phase(0, theta).normalized())};
  };
  for (int m = 1; m <= max_m; ++m) {
    double deviation = 0.0;
    bool within = true;
    for (int i = 0; i < (m + 1) / 2 && within; ++i) {
      const auto [P0, T0] = knot(m, i);
      const auto [P1, T1] = knot(m, i + 1);
      const auto biarc = fit_detail::fit_biarc(P0, T0, P1, T1);
      if (!biarc) {
        return {};
      }
      const double d = fit_detail::biarc_deviation(path, i * shape.delta / m,
                                                   (i + 1) * shape.delta / m, *biarc, tolerance);
      deviation = std::max(deviation, d);
      within = d <= tolerance;
    }
    if (within) {
      return {m, deviation};
    }
  }
  return {};
}

// P21: the smallest m and its deviation, by the scan as written, across tolerances that need
// from one to a few hundred biarcs, and at the boundary (the tolerance equal to a fit's
// deviation, and just below it).
TEST(FitEvaluation, SmallestMIsTheLiteralScans) {
  for (const int N : {3, 4, 6, 9, 12}) {
    const fit_detail::CentrePath path(fit_detail::make_polygon_shape(N, 1.0));
    std::vector<double> tolerances;
    for (double tolerance = 2e-3; tolerance > 1e-9; tolerance /= 4.7) {
      tolerances.push_back(tolerance);
    }
    const auto first = fit_detail::fit_ellipse_arc(path, 1e-7);
    ASSERT_TRUE(first.ok());
    tolerances.push_back(first.value().deviation);
    tolerances.push_back(std::nextafter(first.value().deviation, 0.0));
    for (const double tolerance : tolerances) {
      SCOPED_TRACE(testing::Message() << "N " << N << " tolerance " << tolerance);
      const auto fit = fit_detail::fit_ellipse_arc(path, tolerance);
      const LiteralFit literal = literal_smallest_m(path, tolerance, 1000);
      ASSERT_TRUE(fit.ok());
      EXPECT_EQ(fit.value().m, literal.m);
      EXPECT_EQ(fit.value().deviation, literal.deviation);
    }
  }
}

// P21: a max_m below the answer is tolerance_unreachable, as the scan stopping there says.
TEST(FitEvaluation, MaxMBelowTheAnswerIsUnreachable) {
  const fit_detail::CentrePath path(fit_detail::make_polygon_shape(5, 1.0));
  const auto fit = fit_detail::fit_ellipse_arc(path, 1e-9);
  ASSERT_TRUE(fit.ok());
  const auto capped = fit_detail::fit_ellipse_arc(path, 1e-9, fit.value().m - 1);
  ASSERT_FALSE(capped.ok());
  EXPECT_EQ(capped.error().code, cutcalc::domain::ErrorCode::tolerance_unreachable);
}

// P21: each junction's parameter is the golden section of the exact squared distance, as
// domain/common/golden_section.h computes it, to the bit.
TEST(FitEvaluation, JunctionParameterIsTheGoldenSectionOfTheExactDistance) {
  for (const auto& [N, tolerance] : {std::pair{3, 1e-10}, std::pair{4, 1e-6}, std::pair{5, 3e-4},
                                     std::pair{8, 1e-8}, std::pair{12, 2e-9}}) {
    SCOPED_TRACE(testing::Message() << "N " << N << " tolerance " << tolerance);
    const fit_detail::CentrePath path(fit_detail::make_polygon_shape(N, 1.0));
    const double delta = path.shape().delta;
    const auto fit = fit_detail::fit_ellipse_arc(path, tolerance);
    ASSERT_TRUE(fit.ok());
    const int m = fit.value().m;
    for (int i = 0; i < m; ++i) {
      const Eigen::Vector2d J = fit.value().biarcs[static_cast<std::size_t>(i)].junction;
      auto f = [&](double theta) { return (path.point_in_phase(0, theta) - J).squaredNorm(); };
      const auto s = cutcalc::domain::golden_section_minimum(f, i * delta / m, (i + 1) * delta / m,
                                                             1e-12 * delta, 80);
      ASSERT_EQ(fit.value().junction_theta[static_cast<std::size_t>(i)], s.midpoint()) << i;
    }
  }
}

// programs.md section 4 literally: every block, 513 exact path samples to the printed spiral and
// 129 spiral samples to the nearest of 48 segments of the samples' polyline.
double literal_printed_deviation(const fit_detail::CentrePath& path, double d_mm,
                                 const std::vector<fit_detail::LoopBlock>& blocks,
                                 const fit_detail::PrintedLoop& loop, double mm_per_unit) {
  constexpr double two_pi = 2.0 * std::numbers::pi;
  auto number = [](const std::string& text) {
    double value = 0.0;
    std::from_chars(text.data(), text.data() + text.size(), value);
    return value;
  };
  auto point = [&](const std::string& x, const std::string& y) -> Eigen::Vector2d {
    return Eigen::Vector2d(number(x), number(y)) * mm_per_unit;
  };
  double worst = 0.0;
  Eigen::Vector2d S = point(loop.start_X, loop.start_Y);
  std::vector<Eigen::Vector2d> exact(513);
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const Eigen::Vector2d E = point(loop.blocks[b].X, loop.blocks[b].Y);
    const Eigen::Vector2d C = S + point(loop.blocks[b].I, loop.blocks[b].J);
    const double r0 = (S - C).norm();
    const double r1 = (E - C).norm();
    const double a0 = std::atan2(S.y() - C.y(), S.x() - C.x());
    double sweep = two_pi;
    if (E != S) {
      sweep = std::atan2(E.y() - C.y(), E.x() - C.x()) - a0;
      while (sweep <= 0.0) sweep += two_pi;
      while (sweep > two_pi) sweep -= two_pi;
    }
    auto distance = [&](const Eigen::Vector2d& p) {
      double angle = std::atan2(p.y() - C.y(), p.x() - C.x()) - a0;
      while (angle < 0.0) angle += two_pi;
      while (angle >= two_pi) angle -= two_pi;
      const double f = angle / sweep;
      if (f <= 1.0) return std::fabs((p - C).norm() - (r0 + f * (r1 - r0)));
      return std::min((p - S).norm(), (p - E).norm());
    };
    const double t0 = blocks[b].t_start;
    const double t1 = blocks[b].t_end;
    for (int j = 0; j <= 512; ++j) {
      exact[static_cast<std::size_t>(j)] = d_mm * path.point(t0 + (t1 - t0) * j / 512);
      worst = std::max(worst, distance(exact[static_cast<std::size_t>(j)]));
    }
    for (int k = 0; k <= 128; ++k) {
      const double f = static_cast<double>(k) / 128;
      const double a = a0 + f * sweep;
      const Eigen::Vector2d q =
          C + (r0 + f * (r1 - r0)) * Eigen::Vector2d(std::cos(a), std::sin(a));
      const int centre = static_cast<int>(std::lround(f * 512));
      double nearest = std::numeric_limits<double>::infinity();
      for (int j = std::max(0, centre - 24); j < std::min(512, centre + 24); ++j) {
        const Eigen::Vector2d& p0 = exact[static_cast<std::size_t>(j)];
        const Eigen::Vector2d ab = exact[static_cast<std::size_t>(j + 1)] - p0;
        const double length2 = ab.squaredNorm();
        const double along = std::clamp(length2 > 0.0 ? (q - p0).dot(ab) / length2 : 0.0, 0.0, 1.0);
        nearest = std::min(nearest, (q - (p0 + along * ab)).norm());
      }
      worst = std::max(worst, nearest);
    }
    S = E;
  }
  return worst;
}

// programs.md section 4: the printed deviation equals the literal evaluation for loops of one to
// a few hundred blocks, at 3 to 6 decimals, in mm and in inch.
TEST(FitEvaluation, PrintedDeviationIsTheLiteralEvaluations) {
  struct Case {
    int N;
    double d;
    double tolerance;
    int decimals;
    bool inch;
  };
  for (const Case& c :
       {Case{3, 1e6, 1e-2, 6, false}, Case{3, 2e4, 1e-4, 6, false}, Case{4, 16.0, 1e-3, 4, false},
        Case{5, 300.0, 1e-4, 5, true}, Case{6, 1e5, 1e-3, 3, false}, Case{7, 1e3, 1e-4, 6, false},
        Case{8, 20.0, 5e-4, 4, false}, Case{12, 1e6, 1e-4, 6, false}, Case{12, 5e3, 1e-3, 4, true},
        Case{9, 1.0, 1e-4, 6, false}}) {
    SCOPED_TRACE(testing::Message() << "N " << c.N << " d " << c.d << " tol " << c.tolerance
                                    << " decimals " << c.decimals << (c.inch ? " inch" : " mm"));
    const fit_detail::CentrePath path(fit_detail::make_polygon_shape(c.N, 1.0));
    const auto fit = fit_detail::fit_ellipse_arc(path, c.tolerance / c.d);
    ASSERT_TRUE(fit.ok());
    const auto blocks = fit_detail::loop_blocks(path, fit.value(), 1e-9);
    fit_detail::NumberFormat format;
    format.decimals = c.decimals;
    format.units_per_mm = c.inch ? 1.0 / 25.4 : 1.0;
    const auto loop = fit_detail::print_loop(blocks, c.d, format);
    const double mm_per_unit = 1.0 / format.units_per_mm;
    EXPECT_EQ(fit_detail::printed_path_deviation_mm(path, c.d, blocks, loop, mm_per_unit),
              literal_printed_deviation(path, c.d, blocks, loop, mm_per_unit));
  }
}

}  // namespace
