#include "api/json_number_overflow.h"

#include <cmath>
#include <cstdlib>
#include <limits>

namespace cutcalc::api {
namespace {

// A string that stands where a number was: a client that sends this very string gets not_finite
// instead of not_a_number for it, nothing worse.
constexpr std::string_view kMarkerText =
    "\x01"
    "cutcalc: number beyond a double";
constexpr std::string_view kMarkerJson = "\"\\u0001cutcalc: number beyond a double\"";

bool is_number_char(char c) {
  return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
}

}  // namespace

OverflowRewrite rewrite_overflowing_numbers(std::string_view body) {
  OverflowRewrite out;
  out.padded.reserve(body.size());
  out.marked.reserve(body.size());
  bool in_string = false;
  for (std::size_t i = 0; i < body.size();) {
    const char c = body[i];
    if (in_string) {
      const std::size_t run = c == '\\' && i + 1 < body.size() ? 2 : 1;  // an escape and its char
      in_string = c != '"';
      out.padded.append(body.substr(i, run));
      out.marked.append(body.substr(i, run));
      i += run;
      continue;
    }
    if (c == '-' || (c >= '0' && c <= '9')) {
      std::size_t end = i;
      while (end < body.size() && is_number_char(body[end])) ++end;
      const std::string_view token = body.substr(i, end - i);
      const std::string text(token);  // strtod needs a terminated string
      if (std::isinf(std::strtod(text.c_str(), nullptr))) {
        ++out.numbers;
        out.padded.append("0").append(token.size() - 1, ' ');
        out.marked.append(kMarkerJson);
      } else {
        out.padded.append(token);
        out.marked.append(token);
      }
      i = end;
      continue;
    }
    in_string = c == '"';
    out.padded.push_back(c);
    out.marked.push_back(c);
    ++i;
  }
  return out;
}

void replace_overflow_markers(nlohmann::json& document) {
  if (document.is_string()) {
    if (document.get_ref<const std::string&>() == kMarkerText) {
      document = std::numeric_limits<double>::quiet_NaN();
    }
    return;
  }
  if (document.is_structured()) {
    for (auto& element : document) replace_overflow_markers(element);
  }
}

}  // namespace cutcalc::api
