#pragma once
// Strict parsing of a request body: valid JSON, no duplicate keys, bounded nesting.

#include <string_view>
#include <variant>

#include <nlohmann/json.hpp>

#include "api/problem.h"

namespace cutcalc::api {

inline constexpr int kMaxJsonDepth = 32;

// The parsed document, or a malformed_json problem saying where and why.
std::variant<nlohmann::json, Problem> parse_json_body(std::string_view body);

// True for application/json with optional parameters (charset=utf-8), case-insensitive.
bool is_json_media_type(std::string_view content_type);

}  // namespace cutcalc::api
