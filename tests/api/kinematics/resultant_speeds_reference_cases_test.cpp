// Replays every case of shared/reference/resultant-speeds.json over HTTP against the real server.

#include <gtest/gtest.h>

#include "support/reference_replay.h"

namespace cutcalc::testing {
namespace {

class ResultantSpeedsReferenceCase : public ::testing::TestWithParam<ReferenceCase> {};

TEST_P(ResultantSpeedsReferenceCase, ServiceAnswersAsTheReference) {
  const ReferenceCase& reference = GetParam();
  const nlohmann::json tolerance = reference.data.value("tolerance", nlohmann::json());
  replay_reference_case(reference, tolerance.is_null() ? abs_rel_tolerance({{"abs", 0}, {"rel", 0}})
                                                       : abs_rel_tolerance(tolerance));
}

INSTANTIATE_TEST_SUITE_P(ResultantSpeeds, ResultantSpeedsReferenceCase,
                         ::testing::ValuesIn(load_cases("resultant-speeds.json")),
                         reference_case_name);

}  // namespace
}  // namespace cutcalc::testing
