#pragma once
// The rotor's dimensions, spec polygon-holes.md section 13 (P28-P30): what grinding the tool and
// checking the mating part need. Private to domain/polygon.

#include "domain/polygon/polygon_geometry.h"
#include "domain/polygon/polygon_hole.h"

namespace cutcalc::domain::polygon::detail {

// P28-P30 for the hole `shape` (lengths in the shape's units, angles in degrees).
RotorDimensions rotor_dimensions(const PolygonShape& shape);

}  // namespace cutcalc::domain::polygon::detail
