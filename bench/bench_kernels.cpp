// Micro-benchmarks of the hot loops: neighbour-list builds and the fused GSPH fluid pass,
// on a dam-break-like block of water at rest (hydrostatic), per thread count; the fluid pass
// also with its scalar loop (fluid/gsph_pair_band.h).
// Items processed = particles, so the rate column reads particles per second.
#include <benchmark/benchmark.h>

#include "core/cell_grid.h"
#include "core/parallel.h"
#include "fluid/gsph_fluid_rates.h"
#include "fluid/hydrostatic_init.h"

using namespace slamsph;

namespace {

FluidParticles block(int nx, int ny, double dx) {
  std::vector<Vec2> pts;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) pts.push_back({(i + 0.5) * dx, (j + 0.5) * dx});
  FluidParticles f;
  append_hydrostatic_block(f, pts, dx, ny * dx, {0.0, -9.81}, TaitEos{1000.0, 45.0, 7.0});
  return f;
}

// Arg 2 selects the list: 0 = full lists (every pair from both sides), 1 = what the solver
// builds for the fluid: each pair once, in bands of cell rows, after the cell-order
// permutation (coupling/interaction_lists.cpp).
void BM_NeighbourListBuild(benchmark::State& st) {
  const double dx = 0.0025;
  FluidParticles f = block(static_cast<int>(st.range(0)), static_cast<int>(st.range(0)) / 2, dx);
  const Executor exec(static_cast<int>(st.range(1)));
  const bool banded = st.range(2) != 0;
  const double r = 2.6 * dx * 1.1;
  CellGrid grid;
  NeighbourList nl;
  BandedPairs pairs;
  for (auto _ : st) {
    grid.build(f.x, r);
    if (banded) {
      f.permute(grid.cell_order());
      grid.build(f.x, r);
      build_banded_pairs(f.x, grid, r, exec, pairs);
      benchmark::DoNotOptimize(pairs.half.index.data());
    } else {
      build_neighbour_list(f.x, f.x, grid, r, true, exec, nl);
      benchmark::DoNotOptimize(nl.index.data());
    }
  }
  st.SetItemsProcessed(st.iterations() * static_cast<long>(f.size()));
}
BENCHMARK(BM_NeighbourListBuild)
    ->ArgsProduct({{200, 800}, {1, 2}, {0, 1}})
    ->ArgNames({"nx", "threads", "banded"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_GsphFluidRates(benchmark::State& st) {
  const double dx = 0.0025;
  FluidParticles f = block(static_cast<int>(st.range(0)), static_cast<int>(st.range(0)) / 2, dx);
  const Executor exec(static_cast<int>(st.range(1)));
  const Kernel k(KernelType::WendlandC2, 1.3 * dx);
  const double r = k.support() * 1.1;
  CellGrid grid;
  grid.build(f.x, r);
  f.permute(grid.cell_order());
  grid.build(f.x, r);
  BandedPairs nl;
  build_banded_pairs(f.x, grid, r, exec, nl);
  const GsphParams prm{45.0, 3.0, 0.0, {0.0, -9.81}};
  const PairLoop loop = static_cast<PairLoop>(st.range(2));
  for (auto _ : st) {
    compute_gsph_fluid_rates(f, nl, k, prm, exec, RatePass::Both, loop);
    benchmark::DoNotOptimize(f.a.data());
  }
  st.SetItemsProcessed(st.iterations() * static_cast<long>(f.size()));
}
// Arg 2, PairLoop: 0 = the loop the solver takes (eight AVX-512 lanes, else four AVX2 lanes
// where the CPU has them), 1 = scalar, 2 = four lanes, 3 = eight lanes (scalar where the CPU
// lacks them).
BENCHMARK(BM_GsphFluidRates)
    ->ArgsProduct({{200, 800}, {1, 2}, {0, 1, 2, 3}})
    ->ArgNames({"nx", "threads", "loop"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The water's reorder into cell order at a neighbour rebuild (coupling/interaction_lists.cpp),
// every field of the set. Arg 2: 0 = a fresh copy of each field and a serial gather (the
// reorder before session 22), 1 = the solver's: through scratch storage kept between calls,
// on the executor's threads (core/field_registry.h).
void BM_FluidReorder(benchmark::State& st) {
  FluidParticles f =
      block(static_cast<int>(st.range(0)), static_cast<int>(st.range(0)) / 2, 0.0025);
  const std::size_t n = f.size();
  // The block's rows into cell order, as the first rebuild of a case does (the later ones
  // move fewer particles, and not as far).
  CellGrid grid;
  grid.build(f.x, 2.6 * 0.0025 * 1.1);
  const std::vector<std::uint32_t> perm = grid.cell_order();
  const Executor exec(static_cast<int>(st.range(1)));
  const bool kept = st.range(2) != 0;
  std::vector<std::byte> scratch;
  for (auto _ : st) {
    if (kept) {
      f.permute(perm, scratch, exec);
    } else {
      FluidParticles::visit_fields(f, [&](const FieldSpec&, auto& v) {
        auto old = v;
        for (std::size_t k = 0; k < n; ++k) v[k] = old[perm[k]];
      });
    }
    benchmark::DoNotOptimize(f.x.data());
  }
  st.SetItemsProcessed(st.iterations() * static_cast<long>(n));
}
BENCHMARK(BM_FluidReorder)
    ->ArgsProduct({{200, 800}, {1, 2}, {0, 1}})
    ->ArgNames({"nx", "threads", "kept"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
