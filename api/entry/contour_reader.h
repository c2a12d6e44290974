#pragma once
// JSON contour objects (API.md "Contours") -> domain contours.

#include <optional>

#include "api/field_reader.h"
#include "domain/entry/contour.h"

namespace cutcalc::api::entry {

enum class ContourSide { entry, exit };  // only an exit may be a wall

// Reads the contour object behind `reader`; nullopt when it is absent or its kind is unreadable.
// Field errors go to the reader's error list: a contour returned beside errors must not be used.
std::optional<domain::entry::Contour> read_contour(ObjectReader& reader, ContourSide side);

}  // namespace cutcalc::api::entry
