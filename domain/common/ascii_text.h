#pragma once
// Text of protocols and programs read as they define it: HTTP field names and media types (RFC
// 9110) and G-code words compare ASCII case-insensitively, whatever the locale, and without a libc
// call per character; nothing outside ASCII is ever folded.

#include <algorithm>
#include <string_view>

namespace cutcalc::domain {

constexpr char ascii_lower(char c) {
  return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
}

constexpr char ascii_upper(char c) {
  return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c;
}

constexpr bool iequals_ascii(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return ascii_lower(x) == ascii_lower(y);
         });
}

// Without the whitespace around it (std::isspace's set in the C locale).
constexpr std::string_view trim_space(std::string_view text) {
  constexpr auto is_space = [](char c) { return c == ' ' || (c >= '\t' && c <= '\r'); };
  while (!text.empty() && is_space(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_space(text.back())) text.remove_suffix(1);
  return text;
}

}  // namespace cutcalc::domain
