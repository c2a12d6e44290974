#pragma once
// The geometry of a polygon hole for drawing (spec polygon-holes.md): the ideal N-gon (P1), the
// exact centre path (P6-P9), the predicted hole of the exact motion (P14-P17) and the rotor
// (P11-P13) posed along the loop (section 3). Program coordinates (section 1 frame: hole centre
// at X0 Y0), mm. Inputs are range-checked by the caller (spec section 10).

#include <vector>

#include "domain/common/result.h"

namespace cutcalc::domain::polygon {

struct HoleGeometryParams {
  int faces = 4;                       // N, 3..12
  double inscribed_diameter_mm = 0.0;  // d > 0
};

struct PlanePoint {
  double x_mm = 0.0;
  double y_mm = 0.0;
};

struct RotorPose {
  double phase_deg = 0.0;           // t, rotor rotation since the loop start; phi = -t
  PlanePoint axis;                  // c(t), the tool axis (P7)
  std::vector<PlanePoint> outline;  // the rotor boundary at this pose (P11-P12), open polygon
};

struct HoleGeometry {
  std::vector<PlanePoint> polygon;         // V_j, j = 0..N-1, counter-clockwise (P1)
  std::vector<PlanePoint> centre_path;     // c(t) over one loop from (0, e), open polygon (P7)
  std::vector<PlanePoint> predicted_hole;  // cut outline, counter-clockwise, open (P14-P17)
  std::vector<RotorPose> rotor_positions;  // poses evenly spaced in t over one loop
  PlanePoint corner_vertex;                // V_0, the vertex the corner view centres on
  double corner_view_radius_mm = 0.0;      // frames V_0's rounded corner and some straight side
};

// Samples of P1, P7, P11-P13 and P17 (sizes fixed by N: at most a few thousand points).
// Errors: not_converged (a sample came out non-finite: a bug).
Result<HoleGeometry> sample_hole_geometry(const HoleGeometryParams& params);

}  // namespace cutcalc::domain::polygon
