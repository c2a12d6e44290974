#pragma once
// Numbers beyond a double (1e400) in a request body. The JSON library stops at the first one, but
// such a number is a field error (422 not_finite at its field), not malformed JSON, and it must
// not hide the errors of the other fields: the body is rewritten so that it parses, and the
// number reads as NaN, which the field reader reports at the field's own pointer like any other
// number that is not finite.

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace cutcalc::api {

struct OverflowRewrite {
  std::size_t numbers = 0;  // numbers beyond a double found
  // Each such number as "0" padded with spaces to its length: every other byte keeps its column,
  // so a syntax error elsewhere is reported where the original text has it.
  std::string padded;
  // Each such number as a marker string that replace_overflow_markers() turns into NaN.
  std::string marked;
};

// Finds the number tokens (outside strings) that overflow a double, as the JSON library's own
// reading (strtod) would.
OverflowRewrite rewrite_overflowing_numbers(std::string_view body);

// Every marker string of a document parsed from OverflowRewrite::marked becomes a NaN number.
void replace_overflow_markers(nlohmann::json& document);

}  // namespace cutcalc::api
