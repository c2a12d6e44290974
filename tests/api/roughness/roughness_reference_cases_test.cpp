// Replays every case of shared/reference/roughness-groove-wall.json and
// roughness-bore-milling.json over HTTP against the real server.

#include <gtest/gtest.h>

#include "support/reference_replay.h"

namespace cutcalc::testing {
namespace {

class RoughnessReferenceCase : public ::testing::TestWithParam<ReferenceCase> {};

TEST_P(RoughnessReferenceCase, ServiceAnswersAsTheReference) {
  const ReferenceCase& reference = GetParam();
  const nlohmann::json tolerance = reference.data.value("tolerance", nlohmann::json());
  replay_reference_case(reference, tolerance.is_null() ? abs_rel_tolerance({{"abs", 0}, {"rel", 0}})
                                                       : abs_rel_tolerance(tolerance));
}

INSTANTIATE_TEST_SUITE_P(GrooveWall, RoughnessReferenceCase,
                         ::testing::ValuesIn(load_cases("roughness-groove-wall.json")),
                         reference_case_name);
INSTANTIATE_TEST_SUITE_P(BoreMilling, RoughnessReferenceCase,
                         ::testing::ValuesIn(load_cases("roughness-bore-milling.json")),
                         reference_case_name);

}  // namespace
}  // namespace cutcalc::testing
