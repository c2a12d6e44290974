// Benchmarks of machine time (spec machine-time.md; issue goal): timing the largest polygon
// program the API allows (3 faces, d = 1e6 mm, 0.1 um fit, 62 loops per layer: 199 826 arc
// blocks, LinuxCNC dialect with C words, about 15.8 MB) on a machine with X, Y, Z and C must take
// at most 150 ms on one core, holding the look-ahead queue, not the move list. The counters say
// the program's size and the estimate, so a run shows what it timed.

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <iostream>

#include "bench/domain/bench_support.h"
#include "domain/machine_time/program_time.h"
#include "domain/polygon/polygon_hole.h"

namespace {

namespace mt = cutcalc::domain::machine_time;
namespace polygon = cutcalc::domain::polygon;

const std::string& largest_polygon_program() {
  static const std::string text = [] {
    const auto result = polygon::generate_polygon_hole(
        cutcalc::bench::largest_polygon_program(cutcalc::domain::program::Dialect::linuxcnc));
    cutcalc::bench::require_ok(result, "polygon hole");
    return polygon::program_text(result.value(), true);
  }();
  return text;
}

mt::Machine machining_centre() {
  mt::Machine machine;
  machine.axes[mt::index(mt::Axis::x)] = mt::AxisLimits{36000.0 / 60.0, 4000.0};
  machine.axes[mt::index(mt::Axis::y)] = mt::AxisLimits{36000.0 / 60.0, 4000.0};
  machine.axes[mt::index(mt::Axis::z)] = mt::AxisLimits{36000.0 / 60.0, 4000.0};
  machine.axes[mt::index(mt::Axis::c)] = mt::AxisLimits{18000.0 / 60.0, 3600.0};
  machine.max_linear_velocity_mm_per_s = 36000.0 / 60.0;
  return machine;
}

void BM_ProgramTimeLargestPolygonProgram(benchmark::State& state) {
  mt::ProgramTimeParams params;
  params.program = largest_polygon_program();
  params.machine = machining_centre();
  double estimate_min = 0.0;
  for (auto _ : state) {
    auto outcome = mt::time_program(params);
    const auto* time = std::get_if<mt::ProgramTime>(&outcome);
    if (time == nullptr) {
      std::cerr << "program time: the largest polygon program was refused\n";
      std::abort();
    }
    estimate_min = time->estimated_s / 60.0;
    benchmark::DoNotOptimize(outcome);
  }
  state.counters["program_MB"] = static_cast<double>(params.program.size()) / 1e6;
  state.counters["estimate_min"] = estimate_min;
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(params.program.size()));
}
BENCHMARK(BM_ProgramTimeLargestPolygonProgram)->Unit(benchmark::kMillisecond);

}  // namespace
