// P14-P17 (uncut corners of the exact motion) and P24-P26 (predicted overcut of the programmed
// motion) of spec polygon-holes.md.

#include "domain/polygon/hole_prediction.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>

#include "domain/common/golden_section.h"

namespace cutcalc::domain::polygon::detail {

namespace {

// The sides of the hole, evaluated once per overcut prediction.
class Sides {
 public:
  Sides(const PolygonShape& shape, const Rotor& rotor) : shape_(shape), rotor_(rotor) {
    for (int j = 0; j < shape.N; ++j) {
      alpha_[static_cast<std::size_t>(j)] = shape.alpha(j);
      u_[static_cast<std::size_t>(j)] = shape.u(j);
    }
  }

  // P26
  [[nodiscard]] double penetration(const Eigen::Vector2d& P, double phi) const {
    double worst = -std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < static_cast<std::size_t>(shape_.N); ++j) {
      worst = std::max(worst, P.dot(u_[j]) + rotor_.support(alpha_[j] - phi));
    }
    return worst - shape_.rho;
  }

  [[nodiscard]] double at(const MotionSegment& segment, double fraction) const {
    return penetration(segment.arc.point_at(fraction),
                       segment.phi_start + fraction * (segment.phi_end - segment.phi_start));
  }

 private:
  const PolygonShape& shape_;
  const Rotor& rotor_;
  std::array<double, 12> alpha_{};
  std::array<Eigen::Vector2d, 12> u_{};
};

// P26: golden-section maximum of the penetration over fractions [a, b] of a segment.
double refine_maximum(const Sides& sides, const MotionSegment& segment, double a, double b) {
  const auto negated = [&](double fraction) { return -sides.at(segment, fraction); };
  return -golden_section_minimum(negated, a, b, 1e-7, 40).smallest_value();
}

}  // namespace

// P14
Eigen::Vector2d corner_path(const CentrePath& path, double t) {
  const PolygonShape& shape = path.shape();
  const double theta_1 = -0.5 * std::numbers::pi + 2.0 * std::numbers::pi / shape.M;
  return path.point(t) + shape.r * unit(theta_1 - t);
}

// P15
double corner_gap(const PolygonShape& shape) {
  if (shape.N == 3) {
    return 0.0;
  }
  if (shape.N % 2 == 1) {
    return std::max(0.0, shape.R_c - shape.r - shape.e);
  }
  return std::max(0.0, 2.0 * shape.R_c - shape.A - shape.r);
}

// P16: rho_c = |X'|^3 / |X' x X''| at t* with X' = c' - r n(theta_1 - t + pi/2),
// X'' = c'' - r n(theta_1 - t). P31: for odd N, t* is a phase join where c'' jumps; the phase
// that ends at t* (t* - 0) is taken, not the one floor(t* / delta) would pick.
double corner_wall_min_radius(const CentrePath& path) {
  const PolygonShape& shape = path.shape();
  if (shape.N == 3) {
    return 0.0;
  }
  const double theta_1 = -0.5 * std::numbers::pi + 2.0 * std::numbers::pi / shape.M;
  const double t_star = 0.5 * (shape.N + 1.0) * shape.delta;
  const int phase = shape.N % 2 == 1 ? (shape.N + 1) / 2 - 1 : shape.N / 2;  // ends at / holds t*
  const double theta = t_star - phase * shape.delta;
  const Eigen::Vector2d X1 = path.velocity_in_phase(phase, theta) -
                             shape.r * unit(theta_1 - t_star + 0.5 * std::numbers::pi);
  const Eigen::Vector2d X2 =
      path.acceleration_in_phase(phase, theta) - shape.r * unit(theta_1 - t_star);
  const double speed = X1.norm();
  return speed * speed * speed / std::abs(cross(X1, X2));
}

// P17 (spec section 4 table, kappa_A to 10 digits; N = 4 in closed form, 4 - 2 sqrt3 - pi/6).
double uncut_area_coefficient(int N) {
  constexpr std::array<double, 13> kappa_A{0.0,
                                           0.0,
                                           0.0,
                                           0.0,
                                           0.01229960926,
                                           0.01712724268,
                                           0.01546390230,
                                           0.01260542332,
                                           0.01042766924,
                                           0.008707233905,
                                           0.007351040065,
                                           0.006256762664,
                                           0.005388589461};
  if (N == 4) {
    return 4.0 - 2.0 * std::sqrt(3.0) - std::numbers::pi / 6.0;  // the classical Reuleaux drill
  }
  return kappa_A[static_cast<std::size_t>(std::clamp(N, 0, 12))];
}

// P24, P25
std::vector<MotionSegment> motion_segments(const PolygonShape& shape, const PhaseFit& fit,
                                           const std::vector<LoopBlock>& blocks,
                                           Synchronization synchronization) {
  std::vector<MotionSegment> segments;
  if (synchronization == Synchronization::c_axis && blocks.size() > 1) {
    // P24: phi linear in the block's path fraction between -t_start and -t_end. Blocks starting
    // in phase 0 (with the one across the change to phase 1) represent every block of a later
    // phase; the last block, the second half of the arc split at the start, is its own.
    for (std::size_t b = 0; b < blocks.size(); ++b) {
      const LoopBlock& block = blocks[b];
      if (block.t_start < shape.delta || b + 1 == blocks.size()) {
        segments.push_back(MotionSegment{block.arc, -block.t_start, -block.t_end});
      }
    }
    return segments;
  }
  // P25: phi(s) = -2 pi s / ((N-1) L_u) on the 2 m arcs of ellipse arc 0 (s from the loop start,
  // which is the start of ellipse arc 0). With one block (m = 1) the C axis interpolates over the
  // full circle, i.e. the same law.
  double phase_length = 0.0;
  for (const Biarc& biarc : fit.biarcs) {
    phase_length += biarc.first.length + biarc.second.length;
  }
  const double L_u = shape.N * phase_length;
  const double rate = -2.0 * std::numbers::pi / ((shape.N - 1.0) * L_u);
  double s = 0.0;
  for (const Biarc& biarc : fit.biarcs) {
    for (const FittedArc* arc : {&biarc.first, &biarc.second}) {
      segments.push_back(MotionSegment{*arc, rate * s, rate * (s + arc->length)});
      s += arc->length;
    }
  }
  return segments;
}

// P26
double penetration(const PolygonShape& shape, const Rotor& rotor, const Eigen::Vector2d& P,
                   double phi) {
  return Sides(shape, rotor).penetration(P, phi);
}

// P26
double predicted_overcut(const PolygonShape& shape, const Rotor& rotor,
                         const std::vector<MotionSegment>& segments, int samples_per_segment,
                         bool refine) {
  const Sides sides(shape, rotor);
  const int K = std::max(samples_per_segment, 2) - 1;
  std::vector<double> values(static_cast<std::size_t>(K + 1));
  double worst = 0.0;
  for (const MotionSegment& segment : segments) {
    for (int k = 0; k <= K; ++k) {
      values[static_cast<std::size_t>(k)] = sides.at(segment, static_cast<double>(k) / K);
    }
    for (int k = 0; k <= K; ++k) {
      const double value = values[static_cast<std::size_t>(k)];
      worst = std::max(worst, value);
      const bool left_lower = k == 0 || values[static_cast<std::size_t>(k - 1)] <= value;
      const bool right_lower = k == K || values[static_cast<std::size_t>(k + 1)] <= value;
      if (refine && left_lower && right_lower) {
        const double a = static_cast<double>(std::max(k - 1, 0)) / K;
        const double b = static_cast<double>(std::min(k + 1, K)) / K;
        worst = std::max(worst, refine_maximum(sides, segment, a, b));
      }
    }
  }
  return worst;
}

}  // namespace cutcalc::domain::polygon::detail
