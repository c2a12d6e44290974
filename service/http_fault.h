#pragma once
// What the HTTP engine refused a request for, by itself (service/http_faults.def): a name, never a
// sentence, so that the app answers it from the one catalogue in the client's language.

#include <cstddef>

namespace cutcalc::service {

enum class HttpFault {
#define CUTCALC_HTTP_FAULT(name, status) name,
#include "service/http_faults.def"
#undef CUTCALC_HTTP_FAULT
};

// The status the engine answers `fault` with: 400, 413 or 503.
constexpr int http_status(HttpFault fault) {
  constexpr int kStatuses[] = {
#define CUTCALC_HTTP_FAULT(name, status) status,
#include "service/http_faults.def"
#undef CUTCALC_HTTP_FAULT
  };
  return kStatuses[static_cast<std::size_t>(fault)];
}

}  // namespace cutcalc::service
