#pragma once
// Answers whose members are a domain result's fields under the fields' own names (the spec's
// names: the domain structs and the API share them). CUTCALC_JSON_FIELDS(out, value, a, b, ...)
// writes out["a"] = value.a; out["b"] = value.b; ... into the JSON object `out`, member by member
// (a brace list would build each member through a temporary two-element array, a cost the hot
// endpoints pay on every answer). It is nlohmann's own expansion, the writing half of
// NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE, without the reading half that the answers have no use for.
// Members whose JSON form differs (an enum's name, an optional, a nested object) are written
// beside it by hand.

#include <nlohmann/json.hpp>

// NOLINTBEGIN(cppcoreguidelines-macro-usage): the field names become the keys.
#define CUTCALC_JSON_FIELDS(out, value, ...)                                 \
  do {                                                                       \
    nlohmann::json& nlohmann_json_j = (out);                                 \
    const auto& nlohmann_json_t = (value);                                   \
    NLOHMANN_JSON_EXPAND(NLOHMANN_JSON_PASTE(NLOHMANN_JSON_TO, __VA_ARGS__)) \
  } while (false)
// NOLINTEND(cppcoreguidelines-macro-usage)
