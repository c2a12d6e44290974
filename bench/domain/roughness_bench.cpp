// Benchmarks of the roughness family (spec roughness.md): the groove-wall crest height with a
// target (R1-R8) and the bore-milling cusp solve (B1-B8, B.4), which must stay under 5 us.

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <iostream>
#include <random>
#include <vector>

#include "bench/domain/bench_support.h"
#include "domain/common/milling_sense.h"
#include "domain/roughness/bore_milling.h"
#include "domain/roughness/groove_wall.h"

namespace {

namespace roughness = cutcalc::domain::roughness;
using cutcalc::bench::require_ok;
using cutcalc::domain::MillingSense;

// R.5: rho 0.3, phi1 2 deg, S 0.12 (branch B) with the paper's measured 13.2 um as the target.
void BM_GrooveWallWithTarget(benchmark::State& state) {
  const roughness::GrooveWallParams params{0.12, 0.3, 2.0, 13.2};
  require_ok(roughness::compute_groove_wall_roughness(params), "groove wall");
  for (auto _ : state) {
    auto result = roughness::compute_groove_wall_roughness(params);
    benchmark::DoNotOptimize(result);
  }
}
BENCHMARK(BM_GrooveWallWithTarget);

void bore_cusp(benchmark::State& state, const roughness::BoreMillingParams& params) {
  require_ok(roughness::compute_bore_milling_cusp(params), "bore milling");
  for (auto _ : state) {
    auto result = roughness::compute_bore_milling_cusp(params);
    benchmark::DoNotOptimize(result);
  }
}

// B.6: the paper's Table 1 setting R 81, r 32.4, n 4, S 0.2, up-milling.
void BM_BoreMillingCuspTableOne(benchmark::State& state) {
  bore_cusp(state, {81.0, 32.4, 4, 0.2, MillingSense::up});
}
BENCHMARK(BM_BoreMillingCuspTableOne);

// B.6: small bore, large feed, down-milling (R 20, r 8, n 1, S 2).
void BM_BoreMillingCuspSmallBoreDown(benchmark::State& state) {
  bore_cusp(state, {20.0, 8.0, 1, 2.0, MillingSense::down});
}
BENCHMARK(BM_BoreMillingCuspSmallBoreDown);

// Bracket ending at delta_m, the zero of theta' (B7): R 16, r 0.75, n 11, S 3.08, down.
void BM_BoreMillingCuspBracketAtThetaPrimeZero(benchmark::State& state) {
  bore_cusp(state, {16.0, 0.75, 11, 3.08, MillingSense::down});
}
BENCHMARK(BM_BoreMillingCuspBracketAtThetaPrimeZero);

// The slowest input found over 200 000 random accepted ones (19 evaluations of f: the root sits
// where theta' is small, so rounding noise in f keeps Newton stepping until the bracket closes).
void BM_BoreMillingCuspSlowestFound(benchmark::State& state) {
  bore_cusp(state,
            {188.53134965795994, 53.940788813174422, 15, 244.3076785534665, MillingSense::down});
}
BENCHMARK(BM_BoreMillingCuspSlowestFound);

// 1024 random accepted inputs (R 1-316 mm, r/R 0.03-0.97, n 1-16, f_zb 1e-3 to 2 r), in turn:
// the typical cost including the occasional bisection fallback.
void BM_BoreMillingCuspRandomMix(benchmark::State& state) {
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<roughness::BoreMillingParams> cases;
  while (cases.size() < 1024) {
    roughness::BoreMillingParams p;
    p.bore_radius_mm = std::pow(10.0, 2.5 * unit(rng));
    p.cutter_radius_mm = p.bore_radius_mm * (0.03 + 0.94 * unit(rng));
    p.teeth = 1 + static_cast<int>(16 * unit(rng));
    p.milling = unit(rng) < 0.5 ? MillingSense::up : MillingSense::down;
    const double f_zb_over_r = std::pow(10.0, -3.0 + 3.3 * unit(rng));
    const double R = p.bore_radius_mm;
    const double r = p.cutter_radius_mm;
    p.feed_per_rev_mm = f_zb_over_r * r * p.teeth * (R - r) / R;
    if (roughness::compute_bore_milling_cusp(p).ok()) {
      cases.push_back(p);
    }
  }
  std::size_t i = 0;
  for (auto _ : state) {
    auto result = roughness::compute_bore_milling_cusp(cases[i]);
    benchmark::DoNotOptimize(result);
    i = (i + 1) % cases.size();
  }
}
BENCHMARK(BM_BoreMillingCuspRandomMix);

}  // namespace
