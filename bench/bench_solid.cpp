// Solid step throughput: cases/oscillating_plate.toml (TL-SFPM, hourglass control, no
// fluid) advanced by the driver, one solid step per Simulation::step(). Arguments:
// particles through the plate height, threads. Items = solid particles x steps, so the
// rate column reads solid particle-steps per second.
#include <benchmark/benchmark.h>

#include <string>

#include "app/simulation.h"
#include "io/case_file.h"
#include "io/case_resolution.h"

using namespace slamsph;

namespace {

void BM_ElasticPlateStep(benchmark::State& st) {
  CaseConfig cfg = load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/oscillating_plate.toml");
  rescale_resolution(cfg, 0.02 / static_cast<double>(st.range(0)));
  Simulation sim(cfg, silent_options(static_cast<int>(st.range(1))));
  std::size_t n = 0;
  for (const SolidBody& b : sim.bodies()) n += b.size();
  for (auto _ : st) sim.step();
  st.SetItemsProcessed(st.iterations() * static_cast<long>(n));
  st.counters["particles"] = static_cast<double>(n);
}
BENCHMARK(BM_ElasticPlateStep)
    ->Args({12, 1})
    ->Args({12, 2})
    ->Args({48, 1})
    ->Args({48, 2})
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
