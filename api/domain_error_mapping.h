#pragma once
// The one place where a domain error becomes an HTTP problem (status and JSON Pointer).

#include "api/problem.h"
#include "domain/common/result.h"

namespace cutcalc::api {

Problem to_problem(const domain::DomainError& error);

}  // namespace cutcalc::api
