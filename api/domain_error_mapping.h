#pragma once
// The one place where a domain error becomes an HTTP problem. The code and its sentences come from
// the one list (api/error_codes.def), the limit it states from the error itself; the JSON Pointer
// from the endpoint, which alone knows its field names.

#include <span>
#include <string_view>

#include "api/problem.h"
#include "domain/common/result.h"

namespace cutcalc::api {

// The request member a domain code is about, as one endpoint names it.
struct ErrorPointer {
  domain::ErrorCode code;
  std::string_view pointer;  // RFC 6901, e.g. "/length_mm"
};

// A 422 impossible-input problem with one error: at the member `pointers` gives for its code ("",
// the combination of inputs, for a code not listed), plus the error's index, if any, and with the
// error's limit as `maximum`. not_converged is a bug: logged, answered as a 500.
Problem to_problem(const domain::DomainError& error, std::span<const ErrorPointer> pointers);

}  // namespace cutcalc::api
