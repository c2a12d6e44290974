// Replays every case of shared/reference/entry-length.json and main-time.json over HTTP against
// the real server: status, values within the file's tolerances, error pointers, and the contract.

#include <gtest/gtest.h>

#include "support/reference_replay.h"

namespace cutcalc::testing {
namespace {

class EntryReferenceCase : public ::testing::TestWithParam<ReferenceCase> {};

TEST_P(EntryReferenceCase, ServiceAnswersAsTheReference) {
  const ReferenceCase& reference = GetParam();
  replay_reference_case(reference, entry_file_tolerance(reference.data.at("tolerance")));
}

INSTANTIATE_TEST_SUITE_P(EntryLength, EntryReferenceCase,
                         ::testing::ValuesIn(load_cases("entry-length.json")), reference_case_name);
INSTANTIATE_TEST_SUITE_P(MainTime, EntryReferenceCase,
                         ::testing::ValuesIn(load_cases("main-time.json")), reference_case_name);

TEST(EntryReferenceFiles, HoldTheExpectedNumberOfCases) {
  // The spec announces 20 and 13 public cases; fewer would mean a truncated or moved file.
  EXPECT_GE(load_cases("entry-length.json").size(), 20U);
  EXPECT_GE(load_cases("main-time.json").size(), 13U);
}

}  // namespace
}  // namespace cutcalc::testing
