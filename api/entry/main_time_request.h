#pragma once
// The request fields of POST /v1/main-time, which POST /v1/main-time/program takes too.

#include <vector>

#include "api/field_reader.h"
#include "domain/entry/main_time.h"

namespace cutcalc::api::entry {

// The main-time fields of the request object (the caller rejects unknown fields once it has read
// its own); meaningful only when the reader recorded no error.
domain::entry::MainTimeParams read_main_time_params(ObjectReader& in);

// Which alternatives were sent: checked only once every field is valid on its own.
std::vector<FieldError> main_time_alternative_errors(const ObjectReader& in);

}  // namespace cutcalc::api::entry
