#pragma once
// Content negotiation for answers that have a plain-text form (RFC 9110 section 12.5.1).

#include <string_view>

#include "api/error_catalogue.h"

namespace cutcalc::api {

// True when the Accept header names text/plain and either does not name application/json or
// gives text/plain the higher quality. Wildcards name nothing: "*/*" keeps the JSON default.
bool prefers_plain_text(std::string_view accept);

// The language of problem details for an Accept-Language header (RFC 9110 section 12.5.4, basic
// filtering): the supported language with the highest q among the ranges that name it ("ru",
// "ru-RU"); English when none is named, on a tie, and for "*" or anything unknown.
Language preferred_language(std::string_view accept_language);

}  // namespace cutcalc::api
