#pragma once
// The exact centre path of the rolling rotor (spec polygon-holes.md P1-P10), written for the tests
// from the spec alone: the G-code checker measures the generated programs against it, so it shares
// no code with domain/polygon.

#include <vector>

#include "gcode/vec2.h"

namespace cutcalc::test::gcode {

class ExactCentrePath {
 public:
  // faces N = 3..12, d = inscribed diameter (mm). Hole centre at the origin, side 0 at Y = -d/2.
  ExactCentrePath(int faces, double inscribed_diameter_mm);

  [[nodiscard]] int faces() const { return faces_; }
  [[nodiscard]] double rho() const { return rho_; }                       // P1
  [[nodiscard]] double side() const { return side_; }                     // a, P1
  [[nodiscard]] double circumradius() const { return circumradius_; }     // R_c, P1
  [[nodiscard]] double delta() const { return delta_; }                   // P2
  [[nodiscard]] double q() const { return q_; }                           // P3
  [[nodiscard]] double r() const { return r_; }                           // P4
  [[nodiscard]] double e() const { return e_; }                           // P5
  [[nodiscard]] double semi_axis_a() const { return a_axis_; }            // A, P7
  [[nodiscard]] double semi_axis_b() const { return b_axis_; }            // B, P7
  [[nodiscard]] double r_max() const { return a_axis_ - circumradius_; }  // P9
  // Rotor rotation per loop: N delta = 2 pi / (N - 1).
  [[nodiscard]] double loop_parameter() const { return loop_; }
  // P10 by composite Simpson (independent of the spec's Gauss-Legendre rule).
  [[nodiscard]] double loop_length() const { return loop_length_; }

  // P7 and P8 for any t (taken modulo the loop).
  [[nodiscard]] Vec2 point(double t) const;
  [[nodiscard]] Vec2 derivative(double t) const;
  [[nodiscard]] Vec2 unit_tangent(double t) const;

  struct Nearest {
    double t = 0.0;  // in [0, loop_parameter())
    double distance = 0.0;
    Vec2 point;
  };
  // The nearest point of the closed path: the nearest of a dense sample, then golden-section
  // refinement between its neighbours (bracket <= 1e-14 of the loop).
  [[nodiscard]] Nearest nearest(Vec2 p) const;
  [[nodiscard]] double distance(Vec2 p) const { return nearest(p).distance; }

 private:
  struct Phase {
    int index;     // p mod N
    double theta;  // t - p delta, in [0, delta)
  };
  [[nodiscard]] Phase phase_of(double t) const;

  int faces_;
  double rho_, side_, circumradius_, delta_, q_, r_, e_, a_axis_, b_axis_, loop_;
  double loop_length_ = 0.0;
  std::vector<double> sample_t_;
  std::vector<Vec2> sample_points_;
};

}  // namespace cutcalc::test::gcode
