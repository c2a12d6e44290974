// A calculation stops at its next interruption point once its stop flag is set, and only then:
// the flag of one thread's scope, the long loops of the program writers and of the program timing.

#include "domain/common/interruption.h"

#include <gtest/gtest.h>

#include <atomic>
#include <string>
#include <thread>

#include "domain/machine_time/program_time.h"
#include "domain/polygon/polygon_hole.h"

namespace cutcalc::domain {
namespace {

polygon::PolygonHoleParams square_hole() {
  polygon::PolygonHoleParams params;
  params.faces = 4;
  params.inscribed_diameter_mm = 20.0;
  params.depth_mm = 10.0;
  params.step_down_mm = 1.0;
  params.spindle_speed_rpm = 100.0;
  return params;
}

TEST(Interruption, PointOutsideAnyScopeNeverThrows) { EXPECT_NO_THROW(interruption_point()); }

TEST(Interruption, PointThrowsOnlyOnceTheFlagIsSet) {
  std::atomic<bool> stop{false};
  const InterruptionScope scope(stop);
  EXPECT_NO_THROW(interruption_point());
  stop.store(true);
  EXPECT_THROW(interruption_point(), Interrupted);
}

TEST(Interruption, ScopeEndsWithItsBlockAndBelongsToItsThread) {
  std::atomic<bool> stop{true};
  {
    const InterruptionScope scope(stop);
    bool thrown_elsewhere = false;
    std::thread([&] {
      try {
        interruption_point();
      } catch (const Interrupted&) {
        thrown_elsewhere = true;
      }
    }).join();
    EXPECT_FALSE(thrown_elsewhere);
  }
  EXPECT_NO_THROW(interruption_point());
}

TEST(Interruption, PolygonProgramStopsWhenAskedAndRunsWhenNot) {
  std::atomic<bool> stop{false};
  const InterruptionScope scope(stop);
  const auto hole = polygon::generate_polygon_hole(square_hole());
  ASSERT_TRUE(hole.ok());
  EXPECT_FALSE(polygon::program_text(hole.value()).empty());
  // The fit stops, and so does a program written as it is read.
  stop.store(true);
  EXPECT_THROW(static_cast<void>(polygon::generate_polygon_hole(square_hole())), Interrupted);
  EXPECT_THROW(static_cast<void>(polygon::program_text(hole.value())), Interrupted);
}

TEST(Interruption, ProgramTimingStopsWhenAsked) {
  const std::string program = "G21 G90 G94\nG1 X10 F100\nG1 X20\nM30\n";
  machine_time::ProgramTimeParams params;
  params.program = program;
  std::atomic<bool> stop{true};
  const InterruptionScope scope(stop);
  EXPECT_THROW(static_cast<void>(machine_time::time_program(params)), Interrupted);
}

}  // namespace
}  // namespace cutcalc::domain
