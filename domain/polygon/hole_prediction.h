#pragma once
// The hole actually produced, spec polygon-holes.md sections 4 and 7: the uncut corners of the
// exact motion (P14-P17) and the overcut predicted for the programmed motion (P24-P26).
// Private to domain/polygon.

#include <vector>

#include <Eigen/Core>

#include "domain/polygon/biarc_fit.h"
#include "domain/polygon/centre_path.h"
#include "domain/polygon/fitted_arc.h"
#include "domain/polygon/polygon_geometry.h"
#include "domain/polygon/polygon_hole.h"
#include "domain/polygon/rotor.h"

namespace cutcalc::domain::polygon::detail {

// P14: X(t) = c(t) + r n(theta_1 - t), the path of rotor corner 1 (it rounds vertex V_0).
Eigen::Vector2d corner_path(const CentrePath& path, double t);

// P15: corner_gap_mm g, vertex -> cut wall on the bisector (same units as the shape).
double corner_gap(const PolygonShape& shape);

// P16, P31: the smallest radius of curvature of the corner wall, that of X at
// t* = (N+1) delta / 2 (0 for N = 3).
double corner_wall_min_radius(const CentrePath& path);

// P17: kappa_A(N), the uncut area of all N corners over d^2. Tabulated to 10 digits from the
// spec's table (it depends on N only); N = 3..12.
double uncut_area_coefficient(int N);

// A piece of the programmed motion for P26: the rotor centre runs along `arc` while the rotor
// angle phi goes linearly (in the arc's path fraction) from phi_start to phi_end.
struct MotionSegment {
  FittedArc arc;
  double phi_start = 0.0;
  double phi_end = 0.0;
};

// P24 (c_axis) or P25 (feed_per_rev): the segments of one loop that are not congruent to each
// other (the loop is N-fold congruent: ellipse arc p and the rotor phase at it are arc 0 turned by
// 2 pi p / N and the rotor by p delta, and the rotor is M-fold symmetric).
std::vector<MotionSegment> motion_segments(const PolygonShape& shape, const PhaseFit& fit,
                                           const std::vector<LoopBlock>& blocks,
                                           Synchronization synchronization);

// P24-P26 of one hole: the unit shape's rotor and motion (d = 1), scaled by d_mm.
struct OvercutPrediction {
  PolygonShape unit_shape;
  Rotor rotor;
  std::vector<MotionSegment> segments;
  double d_mm = 0.0;
};

// P26: penetration(P, phi) = max_j (<P, u_j> + h(alpha_j - phi) - rho).
double penetration(const PolygonShape& shape, const Rotor& rotor, const Eigen::Vector2d& P,
                   double phi);

// P26: max(0, the largest penetration over the segments), sampled and refined at each local
// maximum by golden section. samples_per_segment >= 2; refine = false samples only.
double predicted_overcut(const PolygonShape& shape, const Rotor& rotor,
                         const std::vector<MotionSegment>& segments, int samples_per_segment = 24,
                         bool refine = true);

}  // namespace cutcalc::domain::polygon::detail
