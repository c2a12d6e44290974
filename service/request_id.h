#pragma once
// X-Request-Id: the client's id when it is safe to echo and log, a fresh one otherwise.

#include <string>
#include <string_view>

namespace cutcalc::service {

// 1..128 characters of [A-Za-z0-9._-]: anything else could break log lines or headers.
bool is_acceptable_request_id(std::string_view id);

// 16 random hex digits.
std::string generate_request_id();

}  // namespace cutcalc::service
