#pragma once
// Workpiece contours where the end mill enters or leaves (spec entry-and-main-time.md, section 3).
// Units: millimetres and degrees.

#include <optional>

namespace cutcalc::domain::entry {

enum class ContourKind {
  straight,     // straight edge across a strip, at angle_deg from the feed direction
  convex_arc,   // round end of radius R
  concave_arc,  // notch of radius R across a strip
  wall,         // exit only: the tool stops with its periphery at a wall (E22)
};

struct Contour {
  ContourKind kind = ContourKind::straight;
  std::optional<double> width_mm;  // B; optional only for convex_arc (defaults to 2R, E3)
  double radius_mm = 0.0;          // R, arcs only
  double angle_deg = 90.0;         // alpha, straight only; 0 < alpha < 180
};

// B: the part width the contour spans (2R for a convex arc without width_mm).
double part_width_mm(const Contour& contour);

}  // namespace cutcalc::domain::entry
