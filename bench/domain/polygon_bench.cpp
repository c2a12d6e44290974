// Benchmarks of the polygon-hole family (spec polygon-holes.md): the whole program for the
// paper's square (N = 4, d = 16, 1 um fit, depth 0.2, step 0.1, 30 rpm) must take under 1 ms.

#include <benchmark/benchmark.h>

#include "bench/domain/bench_support.h"
#include "domain/polygon/polygon_hole.h"
#include "domain/program/program_options.h"

namespace {

namespace polygon = cutcalc::domain::polygon;

polygon::PolygonHoleParams square_a16(polygon::Synchronization synchronization) {
  polygon::PolygonHoleParams params;
  params.faces = 4;
  params.inscribed_diameter_mm = 16.0;
  params.depth_mm = 0.2;
  params.step_down_mm = 0.1;
  params.spindle_speed_rpm = 30.0;
  params.tolerance_mm = 0.001;
  params.synchronization = synchronization;
  return params;
}

void run(benchmark::State& state, const polygon::PolygonHoleParams& params) {
  cutcalc::bench::require_ok(polygon::generate_polygon_hole(params), "polygon hole");
  for (auto _ : state) {
    auto result = polygon::generate_polygon_hole(params);
    benchmark::DoNotOptimize(result);
  }
}

void BM_PolygonHoleSquareA16FeedPerRev(benchmark::State& state) {
  run(state, square_a16(polygon::Synchronization::feed_per_rev));
}
BENCHMARK(BM_PolygonHoleSquareA16FeedPerRev)->Unit(benchmark::kMicrosecond);

void BM_PolygonHoleSquareA16CAxis(benchmark::State& state) {
  run(state, square_a16(polygon::Synchronization::c_axis));
}
BENCHMARK(BM_PolygonHoleSquareA16CAxis)->Unit(benchmark::kMicrosecond);

// The largest fit of the section 6 table: N = 3, d = 20, 0.5 um (m = 10, 55 blocks per loop).
void BM_PolygonHoleTriangleD20HalfMicron(benchmark::State& state) {
  polygon::PolygonHoleParams params = square_a16(polygon::Synchronization::feed_per_rev);
  params.faces = 3;
  params.inscribed_diameter_mm = 20.0;
  params.tolerance_mm = 0.0005;
  run(state, params);
}
BENCHMARK(BM_PolygonHoleTriangleD20HalfMicron)->Unit(benchmark::kMicrosecond);

// The largest fit the API accepts: N = 3, d = 1e6, 0.1 um (m = 538, 3223 blocks per loop) with a
// Fanuc program at 6 decimals, so the printed-path deviation runs too. The program text is
// streamed later: this is the time before the first byte of the answer.
void BM_PolygonHoleLargestProgramFit(benchmark::State& state) {
  run(state, cutcalc::bench::largest_polygon_program(cutcalc::domain::program::Dialect::fanuc));
}
BENCHMARK(BM_PolygonHoleLargestProgramFit)->Unit(benchmark::kMillisecond);

}  // namespace
