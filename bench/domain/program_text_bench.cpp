// The program writers alone, as the service sends a program: the largest polygon program the API
// allows (N = 3, d = 1 000 000 mm, 0.1 um, 62 loops, c_axis, fanuc, 6 decimals: 15.8 MB) written
// from its fit in the pieces the engine asks for (64 KiB), into one reused buffer as a socket
// would take them. Bytes per second are reported (issue 31: >= 150 MB/s on one core).

#include <benchmark/benchmark.h>

#include <string>

#include "bench/domain/bench_support.h"
#include "domain/polygon/polygon_hole.h"

namespace {

namespace polygon = cutcalc::domain::polygon;
namespace program = cutcalc::domain::program;

constexpr std::size_t kPieceBytes = 64 * 1024;  // service/http_event_loop.cpp

void BM_PolygonLargestProgramText(benchmark::State& state) {
  const auto hole = polygon::generate_polygon_hole(
      cutcalc::bench::largest_polygon_program(program::Dialect::fanuc));
  cutcalc::bench::require_ok(hole, "largest polygon program");
  std::string piece;
  std::size_t bytes = 0;
  for (auto _ : state) {
    const auto source = polygon::open_program_text(hole.value(), true);
    bool more = true;
    while (more) {
      piece.clear();
      more = source->write_next(piece, kPieceBytes);
      bytes += piece.size();
      benchmark::DoNotOptimize(piece.data());
    }
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(bytes));
}
BENCHMARK(BM_PolygonLargestProgramText)->Unit(benchmark::kMillisecond);

}  // namespace
