#pragma once
// Content negotiation for answers that have a plain-text form (RFC 9110 section 12.5.1).

#include <string_view>

namespace cutcalc::api {

// True when the Accept header names text/plain and either does not name application/json or
// gives text/plain the higher quality. Wildcards name nothing: "*/*" keeps the JSON default.
bool prefers_plain_text(std::string_view accept);

}  // namespace cutcalc::api
