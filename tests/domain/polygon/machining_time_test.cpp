// The machining time of spec polygon-holes.md section 13 (P32-P34): each equation on hand-made
// inputs, and the paper's square through generate_polygon_hole (the section's worked figures).

#include <gtest/gtest.h>

#include <cmath>

#include "domain/polygon/machining_time.h"
#include "domain/polygon/polygon_hole.h"
#include "polygon_test_support.h"

namespace {

namespace polygon = cutcalc::domain::polygon;
namespace polygon_detail = polygon::detail;
using polygon::Synchronization;

// N = 4 at 30 rpm, 2 layers of 0.3 mm on a 6 mm loop (dz / L_p = 0.05), 3 loops per layer.
polygon_detail::TimeInputs inputs() {
  polygon_detail::TimeInputs in;
  in.N = 4;
  in.layers = 2.0;
  in.dz_mm = 0.3;
  in.loops_per_layer = 3;
  in.spindle_speed_rpm = 30.0;
  in.loop_length_mm = 6.0;
  in.feed_per_rev_mm = 18.0;
  in.safe_z_mm = 5.0;
  in.depth_mm = 0.6;
  in.rapid_mm_per_min = 10000.0;
  return in;
}

const double kRamp = std::sqrt(1.0 + 0.05 * 0.05);

// P32: n lpl loops of 1 / ((N - 1) S) min each; G95 keeps the loop time on the ramp too.
TEST(PolygonMachiningTime, WorkingTimeIsTheLoopsAtOneLoopPerThirdOfARevolution) {
  EXPECT_NEAR(polygon_detail::machining_time(inputs()).working_min, 6.0 / 90.0, 1e-15);
}

// P32: with one loop per layer a flat loop follows the last layer.
TEST(PolygonMachiningTime, OneLoopPerLayerAddsTheFinalFlatLoop) {
  auto in = inputs();
  in.loops_per_layer = 1;
  EXPECT_NEAR(polygon_detail::machining_time(in).working_min, 3.0 / 90.0, 1e-15);
}

// P32, c_axis: G94 F along XYZ makes each of the n ramp loops longer by the helix factor.
TEST(PolygonMachiningTime, CAxisRampLoopsTakeTheHelixFactorLonger) {
  auto in = inputs();
  in.synchronization = Synchronization::c_axis;
  EXPECT_NEAR(polygon_detail::machining_time(in).working_min,
              6.0 / 90.0 + 2.0 / 90.0 * (kRamp - 1.0), 1e-15);
}

// P33: G95 linuxcnc / sinumerik plunge at the modal ramp F; Fanuc G95 and c_axis at S F_rev.
TEST(PolygonMachiningTime, PlungeRunsAtTheRampFeedOnlyWhereItIsModal) {
  auto in = inputs();
  EXPECT_NEAR(polygon_detail::machining_time(in).plunge_min, 5.0 / (30.0 * 18.0 * kRamp), 1e-15);
  in.plunge_at_ramp_feed = false;
  EXPECT_NEAR(polygon_detail::machining_time(in).plunge_min, 5.0 / (30.0 * 18.0), 1e-15);
  in.plunge_at_ramp_feed = true;
  in.synchronization = Synchronization::c_axis;
  EXPECT_NEAR(polygon_detail::machining_time(in).plunge_min, 5.0 / (30.0 * 18.0), 1e-15);
}

// P34: the final G0 Z from the depth to the safe height; the cycle is the sum.
TEST(PolygonMachiningTime, RapidIsTheFinalRetractAndCycleTheSum) {
  auto in = inputs();
  in.rapid_mm_per_min = 24000.0;
  const auto time = polygon_detail::machining_time(in);
  EXPECT_NEAR(time.rapid_min, 5.6 / 24000.0, 1e-15);
  EXPECT_NEAR(time.cycle_min, time.working_min + time.plunge_min + time.rapid_min, 1e-15);
}

// Section 13's worked figures: the square a = 16 at 30 rpm in 2 layers (G95, linuxcnc).
TEST(PolygonMachiningTime, PaperSquareInTwoLayers) {
  auto params = cutcalc::test::polygon::hole(4, 16.0);
  const auto result = polygon::generate_polygon_hole(params);
  ASSERT_TRUE(result.ok());
  EXPECT_NEAR(result.value().time.working_min, 0.066667, 1e-6);
  EXPECT_NEAR(result.value().time.plunge_min, 0.0069368, 1e-7);
  EXPECT_NEAR(result.value().time.rapid_min, 0.00052, 1e-12);
  EXPECT_NEAR(result.value().corner_radius_mm, 1.5692, 1e-4);
  EXPECT_NEAR(result.value().rotor.neck_diameter_max_mm, 13.5248, 1e-4);
  // A faster rapid changes the rapid time only.
  params.rapid_mm_per_min = 20000.0;
  const auto faster = polygon::generate_polygon_hole(params);
  ASSERT_TRUE(faster.ok());
  EXPECT_NEAR(faster.value().time.rapid_min, 0.00026, 1e-12);
  EXPECT_EQ(faster.value().time.working_min, result.value().time.working_min);
  EXPECT_EQ(cutcalc::domain::polygon::program_text(faster.value()),
            cutcalc::domain::polygon::program_text(result.value()));
}

}  // namespace
