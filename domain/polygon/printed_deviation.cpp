#include "domain/polygon/printed_deviation.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "domain/common/interruption.h"

namespace cutcalc::domain::polygon::detail {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// Samples per block: of the exact path (its polyline's chords sag far below any printed digit)
// and of the printed arc.
constexpr int kDeviationPathSamples = 512;
constexpr int kDeviationArcSamples = 128;
// Printed-arc samples are compared with the exact path near the same fraction of the block.
constexpr int kSearchWindow = 24;

double parse_number(const std::string& text) {
  double value = 0.0;
  std::from_chars(text.data(), text.data() + text.size(), value);
  return value;
}

// One printed block: a spiral from S to E around C, counter-clockwise (G3), as P23 reads it.
struct PrintedArc {
  Eigen::Vector2d S, E, C;
  double r0 = 0.0, r1 = 0.0, a0 = 0.0, sweep = kTwoPi;

  PrintedArc(const Eigen::Vector2d& start, const Eigen::Vector2d& end,
             const Eigen::Vector2d& centre)
      : S(start), E(end), C(centre), r0((start - centre).norm()), r1((end - centre).norm()) {
    a0 = std::atan2(S.y() - C.y(), S.x() - C.x());
    if (E != S) {
      sweep = std::atan2(E.y() - C.y(), E.x() - C.x()) - a0;
      while (sweep <= 0.0) sweep += kTwoPi;
      while (sweep > kTwoPi) sweep -= kTwoPi;
    }
  }
  [[nodiscard]] Eigen::Vector2d at(double f) const {
    const double a = a0 + f * sweep;
    return C + (r0 + f * (r1 - r0)) * Eigen::Vector2d(std::cos(a), std::sin(a));
  }
  // The distance from p to the spiral: radial where p's angle lies on it, else to an end.
  [[nodiscard]] double distance(const Eigen::Vector2d& p) const {
    double angle = std::atan2(p.y() - C.y(), p.x() - C.x()) - a0;
    while (angle < 0.0) angle += kTwoPi;
    while (angle >= kTwoPi) angle -= kTwoPi;
    const double f = angle / sweep;
    if (f <= 1.0) return std::fabs((p - C).norm() - (r0 + f * (r1 - r0)));
    return std::min((p - S).norm(), (p - E).norm());
  }
};

}  // namespace

double printed_path_deviation_mm(const CentrePath& path, double d_mm,
                                 const std::vector<LoopBlock>& blocks, const PrintedLoop& loop,
                                 double mm_per_unit) {
  const auto point = [&](const std::string& x, const std::string& y) -> Eigen::Vector2d {
    return Eigen::Vector2d(parse_number(x), parse_number(y)) * mm_per_unit;
  };
  double worst = 0.0;
  Eigen::Vector2d S = point(loop.start_X, loop.start_Y);
  std::vector<Eigen::Vector2d> exact(kDeviationPathSamples + 1, Eigen::Vector2d::Zero());
  for (std::size_t b = 0; b < blocks.size() && b < loop.blocks.size(); ++b) {
    interruption_point();
    const PrintedBlock& printed = loop.blocks[b];
    const Eigen::Vector2d E = point(printed.X, printed.Y);
    const PrintedArc arc(S, E, S + point(printed.I, printed.J));
    const double t0 = blocks[b].t_start;
    const double t1 = blocks[b].t_end;
    for (int j = 0; j <= kDeviationPathSamples; ++j) {
      const auto i = static_cast<std::size_t>(j);
      exact[i] = d_mm * path.point(t0 + (t1 - t0) * j / kDeviationPathSamples);
      worst = std::max(worst, arc.distance(exact[i]));  // exact path -> printed arc
    }
    for (int k = 0; k <= kDeviationArcSamples; ++k) {  // printed arc -> exact path
      const double f = static_cast<double>(k) / kDeviationArcSamples;
      const Eigen::Vector2d q = arc.at(f);
      const int centre = static_cast<int>(std::lround(f * kDeviationPathSamples));
      double nearest = std::numeric_limits<double>::infinity();
      for (int j = std::max(0, centre - kSearchWindow);
           j < std::min(kDeviationPathSamples, centre + kSearchWindow); ++j) {
        nearest = std::min(nearest, segment_distance(q, exact[static_cast<std::size_t>(j)],
                                                     exact[static_cast<std::size_t>(j + 1)]));
      }
      worst = std::max(worst, nearest);
    }
    S = E;
  }
  return worst;
}

}  // namespace cutcalc::domain::polygon::detail
