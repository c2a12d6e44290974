// Benchmarks of the resultant-speed calculation (spec resultant-speeds.md): the paper's flat with
// the default three points, and the same request with 100 points spread over the arc.

#include <benchmark/benchmark.h>

#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <vector>

#include "domain/kinematics/resultant_speeds.h"

namespace {

namespace kinematics = cutcalc::domain::kinematics;

// Section 6: R1 = 10, R2 = 16, t = 1 (a_w = 25), 3000 / 10 rpm, feed +100 mm/min, up-milling.
kinematics::ResultantSpeedsParams paper_flat() {
  kinematics::ResultantSpeedsParams p;
  p.tool_radius_mm = 10.0;
  p.workpiece_radius_mm = 16.0;
  p.placement = kinematics::FlatDepth{1.0};
  p.tool_speed_rpm = 3000.0;
  p.workpiece_speed_rpm = 10.0;
  p.milling = cutcalc::domain::MillingSense::up;
  p.tool_feed_mm_per_min = 100.0;
  return p;
}

void require_points(const kinematics::ResultantSpeedsParams& params, std::size_t count) {
  const auto result = kinematics::compute_resultant_speeds(params);
  if (!result.ok() || result.value().points.size() != count) {
    std::cerr << "resultant speeds: expected " << count << " points\n";
    std::abort();
  }
}

void BM_ResultantSpeedsDefaultPoints(benchmark::State& state) {
  const auto params = paper_flat();
  require_points(params, 3);
  for (auto _ : state) {
    auto result = kinematics::compute_resultant_speeds(params);
    benchmark::DoNotOptimize(result);
  }
}
BENCHMARK(BM_ResultantSpeedsDefaultPoints);

// 100 points evenly from entry (+20 deg) to exit (-20 deg), inside rho_e = 20.28 deg.
void BM_ResultantSpeeds100Points(benchmark::State& state) {
  auto params = paper_flat();
  std::vector<double> angles;
  for (int i = 0; i < 100; ++i) {
    angles.push_back(20.0 - 40.0 * i / 99.0);
  }
  params.contact_angles_deg = angles;
  require_points(params, angles.size());
  for (auto _ : state) {
    auto result = kinematics::compute_resultant_speeds(params);
    benchmark::DoNotOptimize(result);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(angles.size()));
}
BENCHMARK(BM_ResultantSpeeds100Points);

}  // namespace
