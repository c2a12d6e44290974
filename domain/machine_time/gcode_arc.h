#pragma once
// The centre of a G2/G3 arc from its centre words or its radius, and whether its end point lies
// on its circle, by the rules of LinuxCNC 2.9's interpreter (rs274ngc interp_arc.cc,
// arc_data_ijk and arc_data_r; spec machine-time.md section 4): the tolerances are those of the
// program's units, applied to every dialect.

#include <array>

namespace cutcalc::domain::machine_time::detail {

using PlanePoint = std::array<double, 2>;  // the plane's two axes, in ArcGeometry's order, mm

struct ArcTolerance {
  double radius_mm;  // smallest radius; how far an R arc may miss its end point
  double spiral_mm;  // how much the radius may change from start to end
};

// rs274ngc's defaults, in the units the program is written in (interp_internal.hh).
ArcTolerance arc_tolerance(bool inch);

// Whether the end lies on the circle about `centre` through `start`.
bool centre_fits(const PlanePoint& start, const PlanePoint& end, const PlanePoint& centre,
                 const ArcTolerance& tolerance);

// The centre of the arc of signed radius `radius` (negative: more than a half circle) from
// `start` to `end`, or false when there is none.
bool centre_from_radius(const PlanePoint& start, const PlanePoint& end, double radius,
                        bool clockwise, const ArcTolerance& tolerance, PlanePoint& centre);

}  // namespace cutcalc::domain::machine_time::detail
