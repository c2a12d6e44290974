// P28-P30 of spec polygon-holes.md: the rotor as a dimensioned drawing.

#include "domain/polygon/rotor_dimensions.h"

#include <numbers>

#include "domain/common/numeric.h"
#include "domain/polygon/rotor.h"

namespace cutcalc::domain::polygon::detail {

RotorDimensions rotor_dimensions(const PolygonShape& shape) {
  const Rotor rotor(shape);
  const int N = shape.N;
  const int M = shape.M;
  RotorDimensions dimensions;
  // P28
  dimensions.corners = M;
  dimensions.corner_circle_diameter_mm = 2.0 * shape.r;
  dimensions.corner_angle_deg = 180.0 - 2.0 * shape.delta * kDegPerRad;
  for (int m = 1; m <= N - 2; ++m) {
    const FlankArc arc = rotor.flank_arc(0, m);
    dimensions.flank_arcs.push_back({arc.radius, arc.centre.x(), arc.centre.y(),
                                     arc.normal_begin * kDegPerRad, arc.normal_end * kDegPerRad});
  }
  // P29, P30: h is least in the direction b_min halfway between corners 0 and 1 (the middle arc
  // k = (N-1)/2 for odd N, the junction of arcs N/2 - 1 and N/2 for even N).
  const double b_min = rotor.corner_angle(0) + std::numbers::pi / M;
  const double h_min = rotor.support(b_min);
  dimensions.neck_diameter_max_mm = 2.0 * h_min;
  if (N % 2 == 0) {
    dimensions.width_min_mm = shape.d;  // constant width
    dimensions.width_max_mm = shape.d;
  } else {
    dimensions.width_min_mm = 2.0 * h_min;
    dimensions.width_max_mm = 2.0 * shape.r;  // corner to the opposite corner
  }
  return dimensions;
}

}  // namespace cutcalc::domain::polygon::detail
