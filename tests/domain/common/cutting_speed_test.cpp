#include "domain/common/cutting_speed.h"

#include <gtest/gtest.h>

namespace cutcalc::domain {
namespace {

TEST(CuttingSpeed, SpindleSpeedIs1000VOverPiD) {
  // E30: v = 100 m/min on D = 50 mm.
  EXPECT_NEAR(spindle_speed_rpm_at(100.0, 50.0), 636.6197723675814, 1e-9);
  // One revolution of a 1000/pi mm diameter is 1 m.
  EXPECT_NEAR(spindle_speed_rpm_at(250.0, 1000.0 / 3.141592653589793), 250.0, 1e-9);
}

}  // namespace
}  // namespace cutcalc::domain
