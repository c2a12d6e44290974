// P18-P21 of spec polygon-holes.md: knots, equal-tangent biarcs, the deviation sampling rule,
// the smallest m, the junction parameters and the merged blocks of one loop.

#include "domain/polygon/biarc_fit.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "domain/common/golden_section.h"
#include "domain/common/interruption.h"

namespace cutcalc::domain::polygon::detail {

namespace {

constexpr int kPathSamples = 300;         // P20
constexpr int kArcSamples = 150;          // P20, per arc
constexpr int kGoldenMaxIterations = 80;  // P21

using PathSamples = std::array<Eigen::Vector2d, kPathSamples>;

// (cos, sin) of a0 + k h for k = 0, 1, 2, ... by rotation, re-anchored on the exact values every
// 32 steps (the recurrence alone drifts by about k ulp).
class AngleSteps {
 public:
  AngleSteps(double a0, double h) : a0_(a0), h_(h), cos_h_(std::cos(h)), sin_h_(std::sin(h)) {}

  // The values for step k; k must go 0, 1, 2, ... in order.
  Eigen::Vector2d next(int k) {
    if (k % 32 == 0) {
      const double angle = a0_ + k * h_;
      value_ = Eigen::Vector2d(std::cos(angle), std::sin(angle));
    } else {
      value_ = Eigen::Vector2d(value_.x() * cos_h_ - value_.y() * sin_h_,
                               value_.y() * cos_h_ + value_.x() * sin_h_);
    }
    return value_;
  }

 private:
  double a0_;
  double h_;
  double cos_h_;
  double sin_h_;
  Eigen::Vector2d value_ = Eigen::Vector2d::Zero();
};

// Distance from P to the polyline of the path samples, by a local descent from segment `hint`
// (the arc samples advance along the path, so the nearest segment moves monotonically); `hint`
// is updated to the nearest segment found.
double polyline_distance(const Eigen::Vector2d& P, const PathSamples& samples, int& hint) {
  constexpr int last_segment = kPathSamples - 2;
  auto distance = [&](int i) {
    return segment_distance(P, samples[static_cast<std::size_t>(i)],
                            samples[static_cast<std::size_t>(i + 1)]);
  };
  int best = std::clamp(hint, 0, last_segment);
  double best_distance = distance(best);
  while (best < last_segment) {
    const double next = distance(best + 1);
    if (!(next < best_distance)) {
      break;
    }
    ++best;
    best_distance = next;
  }
  while (best > 0) {
    const double previous = distance(best - 1);
    if (!(previous < best_distance)) {
      break;
    }
    --best;
    best_distance = previous;
  }
  // The neighbours once more guard the descent against ties at a shared vertex.
  if (best > 1) {
    best_distance = std::min(best_distance, distance(best - 2));
  }
  if (best < last_segment - 1) {
    best_distance = std::min(best_distance, distance(best + 2));
  }
  hint = best;
  return best_distance;
}

// P21: theta in [theta0, theta1] of the exact point of ellipse arc 0 nearest to J, by golden
// section until the bracket is <= 1e-12 delta (at most 80 iterations).
std::optional<double> nearest_path_parameter(const CentrePath& path, const Eigen::Vector2d& J,
                                             double theta0, double theta1) {
  const double bracket = 1e-12 * path.shape().delta;
  auto f = [&](double theta) { return (path.point_in_phase(0, theta) - J).squaredNorm(); };
  const GoldenSection s = golden_section_minimum(f, theta0, theta1, bracket, kGoldenMaxIterations);
  if (!(s.b - s.a <= bracket)) {
    return std::nullopt;
  }
  return s.midpoint();
}

// P18: knot i of ellipse arc 0 for m biarcs: theta_i = i delta / m, the exact point and unit
// tangent. The phase-change knots are the exact points -e u_0 = (0, e) and -e u_1 (P9).
struct Knot {
  Eigen::Vector2d P;
  Eigen::Vector2d T;
};

Knot make_knot(const CentrePath& path, int m, int i) {
  const PolygonShape& shape = path.shape();
  const double theta = i * shape.delta / m;
  Knot knot{path.point_in_phase(0, theta), path.velocity_in_phase(0, theta).normalized()};
  if (i == 0) {
    knot.P = Eigen::Vector2d(0.0, shape.e);
  } else if (i == m) {
    knot.P = -shape.e * shape.u(1);
  }
  return knot;
}

// P19 for biarc i of m.
Result<Biarc> make_biarc(const CentrePath& path, int m, int i) {
  const Knot k0 = make_knot(path, m, i);
  const Knot k1 = make_knot(path, m, i + 1);
  const auto biarc = fit_biarc(k0.P, k0.T, k1.P, k1.T);
  if (!biarc) {
    return make_error(ErrorCode::not_converged,
                      "the arc fit of the centre path degenerated (m = " + std::to_string(m) + ")");
  }
  return *biarc;
}

}  // namespace

// P19
std::optional<Biarc> fit_biarc(const Eigen::Vector2d& P0, const Eigen::Vector2d& T0,
                               const Eigen::Vector2d& P1, const Eigen::Vector2d& T1) {
  const Eigen::Vector2d d = P1 - P0;  // the chord vector
  const Eigen::Vector2d v = T0 + T1;
  const double tau = 1.0 - T0.dot(T1);
  const double dv = d.dot(v);
  const double d2 = d.squaredNorm();
  const double al = d2 / (dv + std::sqrt(dv * dv + 2.0 * tau * d2));
  if (!std::isfinite(al) || !(al > 0.0)) {
    return std::nullopt;
  }
  const Eigen::Vector2d Q0 = P0 + al * T0;
  const Eigen::Vector2d Q1 = P1 - al * T1;
  const Eigen::Vector2d J = 0.5 * (Q0 + Q1);
  const Eigen::Vector2d T_J = (Q1 - Q0).normalized();
  const auto first = arc_from_tangent(P0, T0, J);
  const auto second = arc_from_tangent(J, T_J, P1);
  if (!first || !second) {
    return std::nullopt;
  }
  return Biarc{*first, *second, J};
}

// P20
double biarc_deviation(const CentrePath& path, double theta0, double theta1, const Biarc& biarc,
                       double limit) {
  PathSamples samples;
  const double step = (theta1 - theta0) / (kPathSamples - 1);
  AngleSteps psi(theta0 - 0.5 * path.shape().delta, step);
  double deviation = 0.0;
  // Path samples t_k = t_i + k (t_{i+1} - t_i) / 299 to the biarc.
  for (int k = 0; k < kPathSamples; ++k) {
    const Eigen::Vector2d cs = psi.next(k);
    const Eigen::Vector2d P = path.point_at_psi(0, cs.x(), cs.y());
    samples[static_cast<std::size_t>(k)] = P;
    deviation =
        std::max(deviation, std::min(biarc.first.distance_to(P), biarc.second.distance_to(P)));
    if (deviation > limit) {
      return deviation;
    }
  }
  // Arc samples (equally spaced in angle, both ends) to the polyline of the path samples.
  int hint = 0;
  for (const FittedArc* arc : {&biarc.first, &biarc.second}) {
    AngleSteps angle(arc->start_angle, arc->sweep / (kArcSamples - 1));
    for (int k = 0; k < kArcSamples; ++k) {
      const Eigen::Vector2d P = arc->centre + arc->radius * angle.next(k);
      deviation = std::max(deviation, polyline_distance(P, samples, hint));
      if (deviation > limit) {
        return deviation;
      }
    }
  }
  return deviation;
}

// P18-P21
Result<PhaseFit> fit_ellipse_arc(const CentrePath& path, double tolerance, int max_m) {
  const double delta = path.shape().delta;
  for (int m = 1; m <= max_m; ++m) {
    interruption_point();
    PhaseFit fit;
    fit.m = m;
    fit.biarcs.reserve(static_cast<std::size_t>(m));
    // The ellipse arc is mirror-symmetric about its mid-phase line, and so are the knots and
    // the sampling rule: biarc m-1-i is the mirror image of biarc i with the same deviation.
    // A failing m stops at its first biarc beyond the tolerance.
    bool within = true;
    for (int i = 0; i < (m + 1) / 2 && within; ++i) {
      auto biarc = make_biarc(path, m, i);
      if (!biarc.ok()) {
        return biarc.error();
      }
      const double deviation =
          biarc_deviation(path, i * delta / m, (i + 1) * delta / m, biarc.value(), tolerance);
      fit.deviation = std::max(fit.deviation, deviation);
      within = deviation <= tolerance;
      fit.biarcs.push_back(biarc.value());
    }
    if (!within) {
      continue;
    }
    for (int i = (m + 1) / 2; i < m; ++i) {
      auto biarc = make_biarc(path, m, i);
      if (!biarc.ok()) {
        return biarc.error();
      }
      fit.biarcs.push_back(biarc.value());
    }
    for (int i = 0; i < m; ++i) {
      const auto theta =
          nearest_path_parameter(path, fit.biarcs[static_cast<std::size_t>(i)].junction,
                                 i * delta / m, (i + 1) * delta / m);
      if (!theta) {
        return make_error(ErrorCode::not_converged,
                          "the nearest path point to a biarc junction did not converge");
      }
      fit.junction_theta.push_back(*theta);
    }
    return fit;
  }
  return make_limit_error(ErrorCode::tolerance_unreachable, max_m);
}

// P21
std::vector<LoopBlock> loop_blocks(const CentrePath& path, const PhaseFit& fit,
                                   double merge_tolerance) {
  const PolygonShape& shape = path.shape();
  const int m = fit.m;
  std::vector<LoopBlock> blocks;
  double s = 0.0;
  auto add = [&](const FittedArc& arc, double t_end) {
    if (!blocks.empty()) {
      LoopBlock& block = blocks.back();
      const bool same_circle = (arc.centre - block.arc.centre).norm() <= merge_tolerance &&
                               std::abs(arc.radius - block.arc.radius) <= merge_tolerance &&
                               (arc.sweep > 0.0) == (block.arc.sweep > 0.0);
      if (same_circle) {
        block.arc.end = arc.end;
        block.arc.sweep += arc.sweep;
        block.arc.length += arc.length;
        block.t_end = t_end;
        s += arc.length;
        block.s_end = s;
        return;
      }
    }
    const double t_start = blocks.empty() ? 0.0 : blocks.back().t_end;
    const double s_start = s;
    s += arc.length;
    blocks.push_back(LoopBlock{arc, t_start, t_end, s_start, s});
  };
  for (int p = 0; p < shape.N; ++p) {
    const double turn = 2.0 * std::numbers::pi * p / shape.N;
    for (int i = 0; i < m; ++i) {
      const Biarc& biarc = fit.biarcs[static_cast<std::size_t>(i)];
      add(biarc.first.rotated(turn),
          p * shape.delta + fit.junction_theta[static_cast<std::size_t>(i)]);
      add(biarc.second.rotated(turn), static_cast<double>(p * m + i + 1) * shape.delta / m);
    }
  }
  blocks.back().arc.end = Eigen::Vector2d(0.0, shape.e);
  return blocks;
}

}  // namespace cutcalc::domain::polygon::detail
