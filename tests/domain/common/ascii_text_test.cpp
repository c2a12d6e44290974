// Header text compared as RFC 9110 says: ASCII case-insensitively, whitespace around ignored.

#include "domain/common/ascii_text.h"

#include <gtest/gtest.h>

namespace cutcalc::domain {
namespace {

TEST(HeaderText, NamesCompareIgnoringAsciiCaseOnly) {
  EXPECT_TRUE(iequals_ascii("Content-Type", "content-TYPE"));
  EXPECT_TRUE(iequals_ascii("", ""));
  EXPECT_FALSE(iequals_ascii("Accept", "Accept-Language"));
  EXPECT_FALSE(iequals_ascii("Accept", "Acceqt"));
  // Bytes outside ASCII are never folded (a locale's tolower could map 0xC9 to 0xE9).
  EXPECT_FALSE(iequals_ascii("\xC9", "\xE9"));
  EXPECT_FALSE(iequals_ascii("[", "{"));  // 0x5B and 0x7B differ by the case bit but are no letters
}

TEST(HeaderText, TrimmingRemovesSpacesAndTabsAroundOnly) {
  EXPECT_EQ(trim_space(" \t application/json \r\n"), "application/json");
  EXPECT_EQ(trim_space("a b"), "a b");
  EXPECT_EQ(trim_space("   "), "");
  EXPECT_EQ(trim_space(""), "");
}

}  // namespace
}  // namespace cutcalc::domain
