// Benchmarks of the entry-length family (spec entry-and-main-time.md): one pass with an exit over a
// straight edge and over a convex arc, and a main-time setup of N1 = 3 lateral x N2 = 5 depth
// passes.

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <iostream>

#include "bench/domain/bench_support.h"
#include "domain/entry/entry_length.h"
#include "domain/entry/main_time.h"

namespace {

namespace entry = cutcalc::domain::entry;
using cutcalc::bench::require_ok;

entry::Contour straight(double width, double angle_deg = 90.0) {
  entry::Contour c;
  c.kind = entry::ContourKind::straight;
  c.width_mm = width;
  c.angle_deg = angle_deg;
  return c;
}

entry::Contour convex(double radius) {
  entry::Contour c;
  c.kind = entry::ContourKind::convex_arc;
  c.radius_mm = radius;
  return c;
}

entry::EntryLengthParams one_pass(double diameter, double offset, const entry::Contour& in,
                                  const entry::Contour& out, double length) {
  entry::EntryLengthParams p;
  p.cutter_diameter_mm = diameter;
  p.offset_mm = offset;
  p.approach_mm = 2.0;
  p.entry = in;
  entry::ExitSide exit;
  exit.contour = out;
  exit.length_mm = length;
  exit.extra_path_mm = 0.0;
  exit.overrun_mm = 2.0;
  p.exit = exit;
  return p;
}

// Straight entry at 60 degrees, straight exit at 75 degrees, band clipped at a side edge.
void BM_EntryLengthStraight(benchmark::State& state) {
  const auto params = one_pass(30.0, 10.0, straight(40.0, 60.0), straight(40.0, 75.0), 200.0);
  require_ok(entry::compute_entry_length(params), "straight");
  for (auto _ : state) {
    auto result = entry::compute_entry_length(params);
    benchmark::DoNotOptimize(result);
  }
}
BENCHMARK(BM_EntryLengthStraight);

// Convex arc entry and exit R = 25, D = 32, K = 6 (E18 case A).
void BM_EntryLengthConvexArc(benchmark::State& state) {
  const auto params = one_pass(32.0, 6.0, convex(25.0), convex(25.0), 150.0);
  require_ok(entry::compute_entry_length(params), "convex arc");
  for (auto _ : state) {
    auto result = entry::compute_entry_length(params);
    benchmark::DoNotOptimize(result);
  }
}
BENCHMARK(BM_EntryLengthConvexArc);

// N1 = ceil(50 / 20) = 3 lateral passes x N2 = ceil(9 / 2) = 5 depth passes, straight part.
void BM_MainTime3x5(benchmark::State& state) {
  entry::MainTimeParams p;
  p.cutter_diameter_mm = 20.0;
  p.teeth = 4;
  p.speed = entry::CuttingSpeed{150.0};
  p.feed_per_tooth_mm = 0.05;
  p.entry_feed = entry::EntryFeedFactor{0.5};
  p.length_mm = 200.0;
  p.entry = straight(50.0, 70.0);
  p.exit = straight(50.0, 90.0);
  p.allowance = entry::Allowance{50.0, 20.0, 9.0, 2.0};
  const auto check = entry::compute_main_time(p);
  require_ok(check, "main time");
  if (check.value().lateral_passes.size() != 3 || check.value().depth_passes_mm.size() != 5) {
    std::cerr << "main time: expected 3 x 5 passes\n";
    std::abort();
  }
  for (auto _ : state) {
    auto result = entry::compute_main_time(p);
    benchmark::DoNotOptimize(result);
  }
}
BENCHMARK(BM_MainTime3x5);

}  // namespace
