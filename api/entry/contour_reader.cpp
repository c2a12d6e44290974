#include "api/entry/contour_reader.h"

namespace cutcalc::api::entry {

using domain::entry::Contour;
using domain::entry::ContourKind;

namespace {

// 0 < alpha < 180 (spec section 8), and no closer than 0.001 degrees to either end: an edge that
// near parallel to the feed has a cotangent that overflows any size, and no workpiece has it.
const Bounds kAngleBounds{0.001, true, 179.999, true, {}};

std::optional<ContourKind> read_kind(ObjectReader& reader, ContourSide side) {
  const auto name =
      side == ContourSide::entry
          ? reader.required_choice("contour", {"straight", "convex_arc", "concave_arc"})
          : reader.required_choice("contour", {"straight", "convex_arc", "concave_arc", "wall"});
  if (!name) {
    return std::nullopt;
  }
  if (*name == "straight") {
    return ContourKind::straight;
  }
  if (*name == "convex_arc") {
    return ContourKind::convex_arc;
  }
  if (*name == "concave_arc") {
    return ContourKind::concave_arc;
  }
  return ContourKind::wall;
}

}  // namespace

std::optional<Contour> read_contour(ObjectReader& reader, ContourSide side) {
  if (!reader.present()) {
    return std::nullopt;
  }
  const auto kind = read_kind(reader, side);
  if (!kind) {
    return std::nullopt;  // without a kind, no other field can be judged known or unknown
  }
  // Field errors are recorded in the reader; the caller stops before the domain if there are any.
  Contour contour;
  contour.kind = *kind;
  switch (*kind) {
    case ContourKind::straight:
      contour.width_mm = reader.required_number("width_mm", Bounds::positive());
      contour.angle_deg = reader.number_or("angle_deg", kAngleBounds, 90.0);
      break;
    case ContourKind::convex_arc:
      contour.radius_mm = reader.required_number("radius_mm", Bounds::positive()).value_or(0.0);
      contour.width_mm = reader.optional_number("width_mm", Bounds::positive());
      break;
    case ContourKind::concave_arc:
      contour.radius_mm = reader.required_number("radius_mm", Bounds::positive()).value_or(0.0);
      contour.width_mm = reader.required_number("width_mm", Bounds::positive());
      break;
    case ContourKind::wall:
      contour.width_mm = reader.required_number("width_mm", Bounds::positive());
      break;
  }
  reader.reject_unknown_fields();
  return contour;
}

}  // namespace cutcalc::api::entry
