#include "gcode/exact_path.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "domain/common/golden_section.h"

namespace cutcalc::test::gcode {

namespace {

constexpr int kSamplesPerPhase = 64;
constexpr int kSimpsonIntervalsPerPhase = 4000;  // even

}  // namespace

ExactCentrePath::ExactCentrePath(int faces, double inscribed_diameter_mm) : faces_(faces) {
  const double n = faces;
  rho_ = inscribed_diameter_mm / 2.0;
  side_ = inscribed_diameter_mm * std::tan(std::numbers::pi / n);
  circumradius_ = rho_ / std::cos(std::numbers::pi / n);
  delta_ = 2.0 * std::numbers::pi / (n * (n - 1.0));
  const double ratio = std::sin(delta_ / 2.0) / std::sin(std::numbers::pi / n);
  q_ = ratio * ratio;
  r_ = rho_ / (1.0 - q_);
  e_ = r_ * q_;
  a_axis_ = r_ * std::cos(delta_ / 2.0) / std::cos(std::numbers::pi / n);
  b_axis_ = r_ * std::sin(delta_ / 2.0) / std::sin(std::numbers::pi / n);
  loop_ = n * delta_;

  // P10: the speed |c'(psi)| = sqrt(A^2 sin^2 psi + B^2 cos^2 psi) over one phase, times N.
  const auto speed = [&](double psi) {
    return std::hypot(a_axis_ * std::sin(psi), b_axis_ * std::cos(psi));
  };
  const double h = delta_ / kSimpsonIntervalsPerPhase;
  double sum = speed(-delta_ / 2.0) + speed(delta_ / 2.0);
  for (int i = 1; i < kSimpsonIntervalsPerPhase; ++i) {
    sum += (i % 2 == 1 ? 4.0 : 2.0) * speed(-delta_ / 2.0 + i * h);
  }
  loop_length_ = n * sum * h / 3.0;

  const int count = faces_ * kSamplesPerPhase;
  for (int i = 0; i < count; ++i) {
    const double t = loop_ * i / count;
    sample_t_.push_back(t);
    sample_points_.push_back(point(t));
  }
}

ExactCentrePath::Phase ExactCentrePath::phase_of(double t) const {
  double local = std::fmod(t, loop_);
  if (local < 0.0) local += loop_;
  int p = static_cast<int>(std::floor(local / delta_));
  p = std::clamp(p, 0, faces_ - 1);
  return {p, local - p * delta_};
}

Vec2 ExactCentrePath::point(double t) const {
  const Phase ph = phase_of(t);
  const double beta = -std::numbers::pi / 2.0 + (2.0 * ph.index + 1.0) * std::numbers::pi / faces_;
  const Vec2 vertex = circumradius_ * unit_at(beta);
  const Vec2 w = unit_at(beta);
  const Vec2 tangent = unit_at(beta + std::numbers::pi / 2.0);
  const double psi = ph.theta - delta_ / 2.0;
  return vertex - (a_axis_ * std::cos(psi)) * w - (b_axis_ * std::sin(psi)) * tangent;
}

Vec2 ExactCentrePath::derivative(double t) const {
  const Phase ph = phase_of(t);
  const double beta = -std::numbers::pi / 2.0 + (2.0 * ph.index + 1.0) * std::numbers::pi / faces_;
  const Vec2 w = unit_at(beta);
  const Vec2 tangent = unit_at(beta + std::numbers::pi / 2.0);
  const double psi = ph.theta - delta_ / 2.0;
  return (a_axis_ * std::sin(psi)) * w - (b_axis_ * std::cos(psi)) * tangent;
}

Vec2 ExactCentrePath::unit_tangent(double t) const {
  const Vec2 d = derivative(t);
  return (1.0 / norm(d)) * d;
}

ExactCentrePath::Nearest ExactCentrePath::nearest(Vec2 p) const {
  std::size_t best = 0;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < sample_points_.size(); ++i) {
    const Vec2 diff = sample_points_[i] - p;
    const double d2 = dot(diff, diff);
    if (d2 < best_d2) {
      best_d2 = d2;
      best = i;
    }
  }
  const double step = loop_ / static_cast<double>(sample_points_.size());
  const auto dist2 = [&](double t) {
    const Vec2 diff = point(t) - p;
    return dot(diff, diff);
  };
  double t = domain::golden_section_minimum(dist2, sample_t_[best] - step, sample_t_[best] + step,
                                            1e-14 * loop_, 200)
                 .midpoint();
  // The refined minimum is never worse than the sample it started from.
  if (dist2(t) > best_d2) t = sample_t_[best];
  Nearest result;
  result.t = std::fmod(t, loop_);
  if (result.t < 0.0) result.t += loop_;
  result.point = point(result.t);
  result.distance = norm(result.point - p);
  return result;
}

}  // namespace cutcalc::test::gcode
