#pragma once
// Outlines of spec polygon-holes.md for drawing: the rotor boundary (P11-P12) placed by the
// section 3 motion, and the cut wall of an uncut corner (P17's s(gamma), which for N <= 5 is the
// corner path P14). Everything in the units of the shape given (the caller uses d = 1).
// Private to domain/polygon.

#include <vector>

#include <Eigen/Core>

#include "domain/polygon/centre_path.h"
#include "domain/polygon/polygon_geometry.h"
#include "domain/polygon/rotor.h"

namespace cutcalc::domain::polygon::detail {

// The rotor boundary with its axis at `axis` and turned by `phi` (section 3: phi = -t),
// counter-clockwise from corner 0: every flank arc (v, m) of P12 sampled by outward normal angle
// from its start (the first arc of v starts at corner K_v) in steps of at most `max_step` rad, and
// on each arc also the point whose outward normal is a side normal u_j, where the rotor's support
// in that direction (P13) is attained. So the outline touches every side the rotor touches, and
// each arc's end is the next arc's first sample (the client closes the outline).
std::vector<Eigen::Vector2d> rotor_outline(const PolygonShape& shape, const Rotor& rotor,
                                           const Eigen::Vector2d& axis, double phi,
                                           double max_step);

// P17: the distance s from vertex V_0 along the ray n(pi - gamma) (gamma measured from side 0
// towards side 1, 0 <= gamma <= pi - 2 pi / N) to the first crossing of the rotor boundary, minimal
// over the motion of section 3: s(gamma) = min over t of the distance to the rotor placed by P7
// with phi = -t (circles of P12 clipped to their normal ranges). At gamma = 0 and at the polygon's
// angle the ray runs along side 0 or 1: s is then the distance to the side's nearest point the
// rotor touches (its support point for that side, P13), where the straight part begins.
double corner_wall_distance(const CentrePath& path, const Rotor& rotor, double gamma);

// P17: the cut wall of the corner at V_0, V_0 + s(gamma) n(pi - gamma) for `samples` (>= 2)
// angles gamma from side 0 (gamma = 0) to side 1 (gamma = pi - 2 pi / N), spaced closer near the
// sides (where the wall meets them tangentially): counter-clockwise about the hole centre. N = 3
// has no uncut corner: every sample is V_0.
std::vector<Eigen::Vector2d> corner_wall(const CentrePath& path, const Rotor& rotor, int samples);

}  // namespace cutcalc::domain::polygon::detail
