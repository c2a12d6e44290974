// The cycle's refusals and warnings (grooving-cycle.md K3-K5, K23, sections 3.7 and 5.1): every
// error code with its condition and boundary, every warning with its boundary and their order.

#include <gtest/gtest.h>

#include <vector>

#include "domain/grooving/grooving_cycle.h"
#include "domain/grooving/grooving_settings.h"

namespace cutcalc::domain::grooving {
namespace {

using settings::paper_setting;

using program::WarningCode;

ErrorCode refusal(const GroovingCycleParams& p) {
  const auto result = compute_grooving_cycle(p);
  EXPECT_FALSE(result.ok());
  return result.ok() ? ErrorCode::not_converged : result.error().code;
}

std::vector<WarningCode> warning_codes(const GroovingCycleParams& p) {
  const auto result = compute_grooving_cycle(p);
  EXPECT_TRUE(result.ok());
  std::vector<WarningCode> codes;
  if (result.ok()) {
    for (const auto& warning : result.value().warnings) codes.push_back(warning.code);
  }
  return codes;
}

TEST(GroovingCycleErrors, BottomAtOrAboveTheStartIsRefused) {
  GroovingCycleParams p = paper_setting();
  p.groove_depth_mm.reset();
  for (const double bottom : {220.0, 230.0}) {
    p.bottom_diameter_mm = bottom;
    EXPECT_EQ(refusal(p), ErrorCode::bottom_not_below_start) << bottom;
  }
  p.bottom_diameter_mm = 219.9;
  EXPECT_TRUE(compute_grooving_cycle(p).ok());
}

TEST(GroovingCycleErrors, DepthReachingTheAxisIsRefused) {
  // 2h >= D0.
  GroovingCycleParams p = paper_setting();
  p.feed_per_rev_mm = 1.0;
  for (const double depth : {110.0, 120.0}) {
    p.groove_depth_mm = depth;
    EXPECT_EQ(refusal(p), ErrorCode::groove_too_deep) << depth;
  }
  p.groove_depth_mm = 109.9;
  EXPECT_TRUE(compute_grooving_cycle(p).ok());
}

TEST(GroovingCycleErrors, ShiftOrToolAsWideAsTheGrooveIsRefused) {
  GroovingCycleParams p = paper_setting();
  p.shift_mm = 10.4;
  EXPECT_EQ(refusal(p), ErrorCode::shift_too_wide);
  p.shift_mm.reset();
  p.tool_width_mm = 10.4;
  EXPECT_EQ(refusal(p), ErrorCode::tool_too_wide);
  p.tool_width_mm = 11.0;
  EXPECT_EQ(refusal(p), ErrorCode::tool_too_wide);
}

TEST(GroovingCycleErrors, ToolAndShiftThatDoNotAddUpAreRefused) {
  // K3 mismatch, and K4 B <= X2.
  GroovingCycleParams p = paper_setting();
  p.tool_width_mm = 10.1;
  EXPECT_EQ(refusal(p), ErrorCode::tool_and_shift_mismatch);
  p.tool_width_mm = 5.2;
  p.shift_mm = 5.2;
  EXPECT_EQ(refusal(p), ErrorCode::tool_not_wider_than_shift);
}

TEST(GroovingCycleErrors, TwentyThousandRevolutionsAreTheCap) {
  // 5.1: N = 20000 accepted, 20001 refused with the limit stated.
  GroovingCycleParams p = paper_setting();
  p.start_diameter_mm = 1000.0;
  p.feed_per_rev_mm = 0.01;
  p.groove_depth_mm = 200.0;
  const auto accepted = compute_grooving_cycle(p);
  ASSERT_TRUE(accepted.ok());
  EXPECT_EQ(accepted.value().revolutions, 20000);
  p.groove_depth_mm = 200.01;
  const auto refused = compute_grooving_cycle(p);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, ErrorCode::too_many_revolutions);
  ASSERT_TRUE(refused.error().limit.has_value());
  EXPECT_EQ(*refused.error().limit, 20000.0);
}

TEST(GroovingCycleWarnings, ShiftOutsideThePapersRangeWarnsBeyondItsEndsOnly) {
  // K5: X2 < 0.3 or X2 > 0.5.
  GroovingCycleParams p = paper_setting();
  for (const double inside : {0.3, 0.4, 0.5}) {
    p.shift_mm = inside;
    EXPECT_TRUE(warning_codes(p).empty()) << inside;
  }
  for (const double outside : {0.2999, 0.5001, 1.0}) {
    p.shift_mm = outside;
    EXPECT_EQ(warning_codes(p), std::vector{WarningCode::shift_outside_paper_range}) << outside;
  }
  // The default shift of a groove narrower than 0.9 mm (W/3 < 0.3) warns too.
  p.shift_mm.reset();
  p.groove_width_mm = 0.75;
  EXPECT_EQ(warning_codes(p), std::vector{WarningCode::shift_outside_paper_range});
}

TEST(GroovingCycleWarnings, FewerThanFiveRevolutionsWarnThePatternIsNotRepeated) {
  // K23: N < 5.
  GroovingCycleParams p = paper_setting();
  p.groove_depth_mm = 0.48;  // N = 4
  EXPECT_EQ(warning_codes(p), std::vector{WarningCode::pattern_not_repeated});
  p.groove_depth_mm = 0.6;  // N = 5
  EXPECT_TRUE(warning_codes(p).empty());
}

TEST(GroovingCycleWarnings, ConstantSurfaceSpeedWarnsWhenTheBottomNeedsMoreThanTheLimit) {
  // K23: G96 and 1000 v/(pi Db) > n_max; at Db 210.4 that is 130.108 rpm.
  GroovingCycleParams p = paper_setting();
  p.spindle.max_spindle_rpm = 130.0;
  EXPECT_EQ(warning_codes(p), std::vector{WarningCode::spindle_speed_limited});
  p.spindle.max_spindle_rpm = 130.2;
  EXPECT_TRUE(warning_codes(p).empty());
}

TEST(GroovingCycleWarnings, ConstantSpeedOverTheGivenLimitWarns) {
  // K23: G97 and n > max_spindle_rpm (given); equal is fine, absent never warns.
  GroovingCycleParams p = paper_setting();
  p.spindle = {1000.0, std::nullopt, 800.0};
  EXPECT_EQ(warning_codes(p), std::vector{WarningCode::spindle_over_limit});
  p.spindle.max_spindle_rpm = 1000.0;
  EXPECT_TRUE(warning_codes(p).empty());
  p.spindle.max_spindle_rpm.reset();
  EXPECT_TRUE(warning_codes(p).empty());
}

TEST(GroovingCycleWarnings, WarningsComeInTheOrderOfSection37) {
  // spindle_over_limit / spindle_speed_limited, then shift_outside_paper_range, then
  // pattern_not_repeated.
  GroovingCycleParams p = paper_setting();
  p.shift_mm = 0.6;
  p.groove_depth_mm = 0.24;  // N = 2
  p.spindle = {1000.0, std::nullopt, 800.0};
  EXPECT_EQ(warning_codes(p),
            (std::vector{WarningCode::spindle_over_limit, WarningCode::shift_outside_paper_range,
                         WarningCode::pattern_not_repeated}));
  p.spindle = {std::nullopt, 86.0, 100.0};
  EXPECT_EQ(warning_codes(p),
            (std::vector{WarningCode::spindle_speed_limited, WarningCode::shift_outside_paper_range,
                         WarningCode::pattern_not_repeated}));
}

}  // namespace
}  // namespace cutcalc::domain::grooving
