#pragma once
// "up" / "down" in requests and responses <-> domain::MillingSense.

#include <optional>

#include "api/field_reader.h"
#include "domain/common/milling_sense.h"

namespace cutcalc::api {

// The required field `milling`.
std::optional<domain::MillingSense> read_milling(ObjectReader& in);

const char* to_string(domain::MillingSense sense);

}  // namespace cutcalc::api
