#pragma once
// The exact centre path of spec polygon-holes.md section 3: N ellipse arcs (P6-P9) and the loop
// length (P10). t is the rotor rotation since the start (rad); phase p covers
// [p delta, (p+1) delta). Private to domain/polygon.

#include <array>
#include <cmath>
#include <cstddef>

#include <Eigen/Core>

#include "domain/polygon/polygon_geometry.h"

namespace cutcalc::domain::polygon::detail {

class CentrePath {
 public:
  explicit CentrePath(const PolygonShape& shape);

  // P7: c in phase p (taken mod N) at theta = t - p delta (theta may leave [0, delta]: the
  // ellipse of phase p continued).
  [[nodiscard]] Eigen::Vector2d point_in_phase(int p, double theta) const;
  // P7 in phase p from cos(psi) and sin(psi), psi = theta - delta/2 (for sampling loops that
  // step psi by rotation). Inline: the arc fit calls it for every sample.
  [[nodiscard]] Eigen::Vector2d point_at_psi(int p, double cos_psi, double sin_psi) const {
    const Frame& f = frame(p);
    return f.V - shape_.A * cos_psi * f.w - shape_.B * sin_psi * f.t;
  }
  // P8: c' and c'' in phase p at theta.
  [[nodiscard]] Eigen::Vector2d velocity_in_phase(int p, double theta) const;
  // point_in_phase and velocity_in_phase together, the same values from one cosine and sine.
  struct PointAndVelocity {
    Eigen::Vector2d point;
    Eigen::Vector2d velocity;
  };
  [[nodiscard]] PointAndVelocity point_and_velocity_in_phase(int p, double theta) const;
  [[nodiscard]] Eigen::Vector2d acceleration_in_phase(int p, double theta) const;

  // P7, P8 at any t >= 0 (the phase is floor(t / delta)).
  [[nodiscard]] Eigen::Vector2d point(double t) const;
  [[nodiscard]] Eigen::Vector2d velocity(double t) const;
  [[nodiscard]] Eigen::Vector2d acceleration(double t) const;

  // P10: L, the exact loop length (40-point Gauss-Legendre per ellipse arc).
  [[nodiscard]] double loop_length() const;

  [[nodiscard]] const PolygonShape& shape() const { return shape_; }

  // The constants of P7 in phase p: c = V - A cos(psi) w - B sin(psi) t.
  struct Frame {
    Eigen::Vector2d V;  // V_p
    Eigen::Vector2d w;  // w_p = n(beta_p)
    Eigen::Vector2d t;  // t_p = n(beta_p + pi/2)
  };
  // p taken mod N.
  [[nodiscard]] const Frame& frame(int p) const {
    const int index = ((p % shape_.N) + shape_.N) % shape_.N;
    return frames_[static_cast<std::size_t>(index)];
  }
  // floor(t / delta), the phase that point(t) evaluates.
  [[nodiscard]] int phase_of(double t) const {
    return static_cast<int>(std::floor(t / shape_.delta));
  }

 private:
  PolygonShape shape_;
  std::array<Frame, 12> frames_{};
};

}  // namespace cutcalc::domain::polygon::detail
