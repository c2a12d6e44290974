// The entry reference files are whole; their cases are replayed over HTTP by
// tools/contract/replay.mjs (ctest ReferenceReplay.EveryCaseOverHttp).

#include <gtest/gtest.h>

#include "support/reference_cases.h"

namespace cutcalc::testing {
namespace {

TEST(EntryReferenceFiles, HoldTheExpectedNumberOfCases) {
  // The spec announces 20 and 13 public cases; fewer would mean a truncated or moved file.
  EXPECT_GE(load_cases("entry-length.json").size(), 20U);
  EXPECT_GE(load_cases("main-time.json").size(), 13U);
}

}  // namespace
}  // namespace cutcalc::testing
