#pragma once
// The wire name of a crest branch (roughness.md R3-R5): "nose_arc", ...

#include "domain/roughness/groove_wall.h"

namespace cutcalc::api::roughness {

const char* to_string(domain::roughness::CrestBranch branch);

}  // namespace cutcalc::api::roughness
