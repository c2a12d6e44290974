// P6-P10 of spec polygon-holes.md: the centre path as N ellipse arcs and its length.

#include "domain/polygon/centre_path.h"

#include <cmath>
#include <cstddef>
#include <numbers>

namespace cutcalc::domain::polygon::detail {

namespace {

constexpr int kGaussPoints = 40;

struct GaussLegendre {
  std::array<double, kGaussPoints> x{};
  std::array<double, kGaussPoints> w{};
};

// Nodes and weights of the 40-point Gauss-Legendre rule on [-1, 1]: Newton on P_40 from the
// Chebyshev-like first guesses, converged to full double precision.
GaussLegendre make_gauss_legendre() {
  GaussLegendre rule;
  constexpr int n = kGaussPoints;
  for (int i = 0; i < n / 2; ++i) {
    double z = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double dp = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0;
      double p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1.0);
      const double step = p1 / dp;
      z -= step;
      if (std::abs(step) < 1e-16) {
        break;
      }
    }
    const double weight = 2.0 / ((1.0 - z * z) * dp * dp);
    rule.x[static_cast<std::size_t>(i)] = -z;
    rule.x[static_cast<std::size_t>(n - 1 - i)] = z;
    rule.w[static_cast<std::size_t>(i)] = weight;
    rule.w[static_cast<std::size_t>(n - 1 - i)] = weight;
  }
  return rule;
}

const GaussLegendre& gauss_legendre() {
  static const GaussLegendre rule = make_gauss_legendre();  // immutable after thread-safe init
  return rule;
}

}  // namespace

CentrePath::CentrePath(const PolygonShape& shape) : shape_(shape) {
  for (int p = 0; p < shape.N; ++p) {
    const double beta = shape.beta(p);
    frames_[static_cast<std::size_t>(p)] =
        Frame{shape.vertex(p), unit(beta), unit(beta + 0.5 * std::numbers::pi)};
  }
}

// P7: c = V_p - A cos(psi) w_p - B sin(psi) t_p, psi = theta - delta/2.
Eigen::Vector2d CentrePath::point_in_phase(int p, double theta) const {
  const Frame& f = frame(p);
  const double psi = theta - 0.5 * shape_.delta;
  return f.V - shape_.A * std::cos(psi) * f.w - shape_.B * std::sin(psi) * f.t;
}

// P8: c' = A sin(psi) w_p - B cos(psi) t_p.
Eigen::Vector2d CentrePath::velocity_in_phase(int p, double theta) const {
  const Frame& f = frame(p);
  const double psi = theta - 0.5 * shape_.delta;
  return shape_.A * std::sin(psi) * f.w - shape_.B * std::cos(psi) * f.t;
}

// P7, P8: the expressions of point_in_phase and velocity_in_phase.
CentrePath::PointAndVelocity CentrePath::point_and_velocity_in_phase(int p, double theta) const {
  const Frame& f = frame(p);
  const double psi = theta - 0.5 * shape_.delta;
  const double c = std::cos(psi);
  const double s = std::sin(psi);
  return {f.V - shape_.A * c * f.w - shape_.B * s * f.t, shape_.A * s * f.w - shape_.B * c * f.t};
}

// P8: c'' = A cos(psi) w_p + B sin(psi) t_p.
Eigen::Vector2d CentrePath::acceleration_in_phase(int p, double theta) const {
  const Frame& f = frame(p);
  const double psi = theta - 0.5 * shape_.delta;
  return shape_.A * std::cos(psi) * f.w + shape_.B * std::sin(psi) * f.t;
}

Eigen::Vector2d CentrePath::point(double t) const {
  const int p = phase_of(t);
  return point_in_phase(p, t - p * shape_.delta);
}

Eigen::Vector2d CentrePath::velocity(double t) const {
  const int p = phase_of(t);
  return velocity_in_phase(p, t - p * shape_.delta);
}

Eigen::Vector2d CentrePath::acceleration(double t) const {
  const int p = phase_of(t);
  return acceleration_in_phase(p, t - p * shape_.delta);
}

// P10: L = N * integral_{-delta/2}^{delta/2} sqrt(A^2 sin^2 psi + B^2 cos^2 psi) dpsi.
double CentrePath::loop_length() const {
  const GaussLegendre& rule = gauss_legendre();
  const double half = 0.5 * shape_.delta;
  double sum = 0.0;
  for (std::size_t k = 0; k < rule.x.size(); ++k) {
    const double psi = half * rule.x[k];
    const double s = shape_.A * std::sin(psi);
    const double c = shape_.B * std::cos(psi);
    sum += rule.w[k] * std::sqrt(s * s + c * c);
  }
  return shape_.N * half * sum;
}

}  // namespace cutcalc::domain::polygon::detail
