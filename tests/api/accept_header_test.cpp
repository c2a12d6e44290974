#include "api/accept_header.h"

#include <gtest/gtest.h>

namespace cutcalc::api {
namespace {

TEST(AcceptHeader, JsonIsTheDefault) {
  EXPECT_FALSE(prefers_plain_text(""));
  EXPECT_FALSE(prefers_plain_text("*/*"));
  EXPECT_FALSE(prefers_plain_text("application/json"));
  EXPECT_FALSE(prefers_plain_text("text/*"));
}

TEST(AcceptHeader, NamedTextPlainWithoutJsonChoosesText) {
  EXPECT_TRUE(prefers_plain_text("text/plain"));
  EXPECT_TRUE(prefers_plain_text("TEXT/PLAIN; charset=us-ascii"));
  EXPECT_TRUE(prefers_plain_text("text/plain, */*;q=0.1"));
}

TEST(AcceptHeader, HigherQualityDecidesWhenBothAreNamed) {
  EXPECT_TRUE(prefers_plain_text("application/json;q=0.5, text/plain"));
  EXPECT_FALSE(prefers_plain_text("application/json, text/plain;q=0.9"));
  EXPECT_FALSE(prefers_plain_text("application/json, text/plain"));  // a tie keeps JSON
}

TEST(AcceptHeader, ZeroOrMalformedQualityNeverChoosesText) {
  EXPECT_FALSE(prefers_plain_text("text/plain;q=0"));
  EXPECT_FALSE(prefers_plain_text("text/plain;q=abc"));
  EXPECT_FALSE(prefers_plain_text("text/plain;q=2"));
}

}  // namespace
}  // namespace cutcalc::api
