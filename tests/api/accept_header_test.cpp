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

TEST(AcceptLanguage, EnglishIsTheDefault) {
  EXPECT_EQ(preferred_language(""), Language::en);
  EXPECT_EQ(preferred_language("*"), Language::en);
  EXPECT_EQ(preferred_language("de-DE, fr;q=0.8"), Language::en);  // unknown: English
  EXPECT_EQ(preferred_language("en"), Language::en);
  EXPECT_EQ(preferred_language("russian"), Language::en);  // not the tag ru
}

TEST(AcceptLanguage, RussianWhenItRanksFirst) {
  EXPECT_EQ(preferred_language("ru"), Language::ru);
  EXPECT_EQ(preferred_language("RU-ru"), Language::ru);
  EXPECT_EQ(preferred_language("ru-RU,ru;q=0.9,en-US;q=0.8,en;q=0.7"), Language::ru);
  EXPECT_EQ(preferred_language("de, ru;q=0.5"), Language::ru);  // the only supported one named
  EXPECT_EQ(preferred_language("en;q=0.3, ru;q=0.9"), Language::ru);
}

TEST(AcceptLanguage, QualityThenOrderDecide) {
  EXPECT_EQ(preferred_language("en-GB, ru;q=0.9"), Language::en);
  EXPECT_EQ(preferred_language("ru, en"), Language::ru);  // equal q: the first listed
  EXPECT_EQ(preferred_language("en, ru"), Language::en);
  EXPECT_EQ(preferred_language("ru;q=0"), Language::en);  // q=0: "not acceptable"
  EXPECT_EQ(preferred_language("ru;q=2"), Language::en);  // malformed q counts as 0
}

}  // namespace
}  // namespace cutcalc::api
