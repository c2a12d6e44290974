// Benchmarks of the pass program (spec programs.md section 1): the worked example of
// entry-and-main-time.md (N1 = 2 lateral x N2 = 3 depth passes) written as a LinuxCNC program in
// mm and as a Fanuc program in inches, from its computed main time (the main time itself is
// measured in entry_bench.cpp).

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <iostream>
#include <string>

#include "domain/entry/main_time.h"
#include "domain/program/pass_program.h"

namespace {

namespace entry = cutcalc::domain::entry;
namespace program = cutcalc::domain::program;

entry::MainTimeParams worked_example() {
  entry::MainTimeParams p;
  p.cutter_diameter_mm = 50.0;
  p.teeth = 4;
  p.speed = entry::SpindleSpeed{1000.0};
  p.feed_per_tooth_mm = 0.1;
  p.entry_feed = entry::EntryFeedFactor{0.5};
  p.length_mm = 120.0;
  p.entry.kind = entry::ContourKind::straight;
  p.entry.width_mm = 80.0;
  p.exit = p.entry;
  p.allowance = {80.0, 45.0, 5.0, 2.0};
  return p;
}

void write(benchmark::State& state, const program::ProgramOptions& options) {
  const entry::MainTimeParams params = worked_example();
  const auto main_time = entry::compute_main_time(params);
  if (!main_time.ok()) {
    std::cerr << "worked example failed: " << main_time.error().detail << "\n";
    std::abort();
  }
  for (auto _ : state) {
    auto written = program::write_pass_program(params, main_time.value(), options, {});
    if (!written.ok()) {
      std::cerr << "worked example program failed: " << written.error().detail << "\n";
      std::abort();
    }
    std::string text = program::program_text(written.value());  // the model, then its text
    benchmark::DoNotOptimize(text);
  }
}

void BM_PassProgramWorkedExampleLinuxcncMm(benchmark::State& state) { write(state, {}); }
BENCHMARK(BM_PassProgramWorkedExampleLinuxcncMm);

void BM_PassProgramWorkedExampleFanucInch(benchmark::State& state) {
  program::ProgramOptions options;
  options.dialect = program::Dialect::fanuc;
  options.units = program::Units::inch;
  write(state, options);
}
BENCHMARK(BM_PassProgramWorkedExampleFanucInch);

}  // namespace
