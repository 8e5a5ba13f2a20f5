// Solid step throughput. Items = solid particles x sub-steps, so the rate column reads solid
// particle-steps per second.
//  - BM_ElasticPlateStep: cases/oscillating_plate.toml (TL-SFPM, hourglass control, no
//    fluid) advanced by the driver, one solid step per Simulation::step(). Arguments:
//    particles through the plate height, threads.
//  - BM_RingSubsteps: an aluminium ring skin (geometry/polar_lattice.h, radially aligned
//    layers, TL-SFPM, SVK, artificial viscosity and hourglass control on) in free vibration
//    of its n = 2 mode, advanced by advance_body over 20 stable steps per iteration (the
//    sub-step loop alone, no fluid). Arguments: case (0: 2 layers, 2 514 particles, r 0.3 m;
//    1: 4 layers, 10 052; 2: 6 layers, 60 000, r 0.8 m; 3 mm skin each), threads. All three
//    run the two-pass schedule of the sub-steps with its pair loops in lanes on an AVX-512F
//    CPU; elsewhere case 2 runs the wavefront schedule (solid/elastic_substep.h, bodies of
//    >= 20 000 particles), cases 0 and 1 the two-pass one. The `band` counter (largest
//    |i - j| of a pair in the stored order) is not what the wavefront needs: it runs over
//    the pair graph's levels (solid/substep_levels.h).
//  - BM_RingSubstepsJohnsonCook: the same rings with the Johnson–Cook law (the Al 2024-T3
//    preset's flow stress, heating, EOS and failure constants; the same E and ν as above,
//    so the sub-step count is comparable). The mode stays elastic (stress ~10 MPa against
//    A = 265 MPa): the rate ratio to BM_RingSubsteps is the cost of the law's elastic path
//    (issue 11: at most 2x the SVK sub-step).
//  - BM_RingSubstepsJohnsonCookYielding: the 2-layer Johnson–Cook ring given 100 m/s radially
//    outward: its hoop strain passes the yield strain (0.4 %) after ~12 µs and it keeps
//    flowing, decelerated by its hoop stress, for the fixed 100 iterations of 20 sub-steps
//    (~200 µs, plastic strain ~4 %, under the failure strain 0.19), so nearly every
//    particle-sub-step runs the return mapping; counter `yielding` the fraction of particles
//    whose plastic strain grew in an iteration, averaged. Its rate against
//    BM_RingSubstepsJohnsonCook is the cost of yielding (app/cost_model.h
//    johnson_cook_yield_factor).
//  - BM_RingSubstepsPairLoop: the SVK rings of case 0 and of case 3 (2 layers, 240
//    particles: a body the size of cases/breached_plate.toml's plate) with the pair loops
//    forced to the lanes or the scalar loops: the per-sub-step cost a small body pays.
//  - BM_RingSubstepsEulerian: the Johnson–Cook rings with a sector failed at the start,
//    its failed particles kept in the total-Lagrangian sums or switched to the Eulerian path
//    (solid/eulerian_failed_interaction.h): the Eulerian path's cost (app/cost_model.h).
// Callgrind: `valgrind --tool=callgrind --toggle-collect='slamsph::advance_body*'
//   build/bench/bench_solid --benchmark_filter='BM_RingSubsteps/case:0/threads:1'
//   --benchmark_min_time=0` counts the sub-step loop only (notes: instructions per
//   particle-step = Ir / (particles x sub-steps)).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "app/simulation.h"
#include "core/parallel.h"
#include "geometry/polar_lattice.h"
#include "geometry/structure_order.h"
#include "io/case_file.h"
#include "io/case_resolution.h"
#include "solid/body_dynamics.h"
#include "solid/elastic_substep.h"
#include "solid/materials/johnson_cook.h"
#include "solid/materials/material_presets.h"

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

// A 3 mm aluminium ring skin: mid radius and layers of each benchmark case.
struct RingCase {
  double r_mid;
  int layers;
};
// Case 3 (2 layers, 240 particles, r 28.6 mm) is the size of cases/breached_plate.toml's
// plate: the small body of BM_RingSubstepsPairLoop and BM_RingSubstepsEulerian.
constexpr RingCase kRings[] = {{0.3, 2}, {0.3, 4}, {0.7958, 6}, {0.0286, 2}};

// `failed`: the fraction of the ring's circumference (a sector about +x) whose particles
// start failed (a Johnson–Cook ring; as `[body.pre_failed]` of a case).
SolidBody aluminium_ring(const RingCase& rc, bool johnson_cook = false, double failed = 0.0) {
  const double t = 0.003;
  // Stored along the structure, as the case builder stores every elastic body
  // (geometry/structure_order.h).
  const ParticleLattice lat = ordered_along_structure(
      ring({0.0, 0.0}, rc.r_mid - 0.5 * t, rc.r_mid + 0.5 * t, rc.layers), t / rc.layers);
  const double rho = 2700.0;
  SolidBody b;
  b.X = lat.x;
  b.x = lat.x;
  b.V0 = lat.volume;
  b.layer = lat.layer;
  for (double v : lat.volume) {
    b.m.push_back(rho * v);
    b.rho0.push_back(rho);
  }
  BodySetup cfg;
  cfg.name = "ring";
  cfg.dx = t / rc.layers;
  cfg.gravity = false;
  ElasticMaterialInput mat;
  mat.name = "aluminium";
  mat.density = rho;
  mat.youngs_modulus = 70e9;
  mat.poisson_ratio = 0.3;
  mat.hourglass = 0.1;
  if (johnson_cook) mat.model = kAl2024T3.model;
  cfg.material = mat;
  if (failed > 0.0) {
    const double half = std::numbers::pi * rc.r_mid * failed;  // half the sector's arc
    cfg.pre_failed_boxes.push_back(Box{{0.0, -half}, {2.0 * rc.r_mid, half}});
  }
  setup_body(b, cfg);
  // n = 2 ovalisation mode, 1 m/s radial amplitude: half the pairs approach (viscosity on).
  for (std::size_t i = 0; i < b.size(); ++i) {
    const double th = std::atan2(b.X[i].y, b.X[i].x);
    const Vec2 er{std::cos(th), std::sin(th)};
    b.v[i] = std::cos(2.0 * th) * er;
  }
  return b;
}

void ring_substeps(benchmark::State& st, bool johnson_cook, double expansion = 0.0) {
  SolidBody b = aluminium_ring(kRings[st.range(0)], johnson_cook);
  if (expansion > 0.0)
    for (std::size_t i = 0; i < b.size(); ++i) b.v[i] = expansion / norm(b.X[i]) * b.X[i];
  const Executor exec(static_cast<int>(st.range(1)));
  double t = 0.0;
  long substeps = 0;
  // The fraction of particles whose plastic strain grew in an iteration (Johnson–Cook only).
  const bool plastic = johnson_cook && !b.history.values.empty();
  std::vector<double> ep;
  double yielding = 0.0;
  long iterations = 0;
  for (auto _ : st) {
    if (plastic) ep = b.history.values[JohnsonCook::kPlasticStrain];
    const double dt = 20.0 * stable_time_step(b) * (1.0 - 1e-9);
    advance_body(b, t, dt, {}, exec);
    t += dt;
    substeps += b.last_substeps;
    if (plastic) {
      st.PauseTiming();
      std::size_t grew = 0;
      for (std::size_t i = 0; i < b.size(); ++i)
        grew += b.history.values[JohnsonCook::kPlasticStrain][i] > ep[i];
      yielding += static_cast<double>(grew) / static_cast<double>(b.size());
      ++iterations;
      st.ResumeTiming();
    }
  }
  if (plastic) st.counters["yielding"] = yielding / static_cast<double>(std::max(1L, iterations));
  st.SetItemsProcessed(substeps * static_cast<long>(b.size()));
  st.counters["particles"] = static_cast<double>(b.size());
  st.counters["substeps"] = static_cast<double>(substeps);
  // Pairs per particle and the largest |j - i| of a pair (the band of the stored order).
  std::size_t band = 0;
  for (std::size_t i = 0; i < b.size(); ++i)
    for (std::uint32_t k = b.topology.pairs.start[i]; k < b.topology.pairs.start[i + 1]; ++k) {
      const std::size_t j = b.topology.pairs.index[k];
      band = std::max(band, j > i ? j - i : i - j);
    }
  st.counters["pairs"] =
      static_cast<double>(b.topology.pairs.index.size()) / static_cast<double>(b.size());
  st.counters["band"] = static_cast<double>(band);
}

void BM_RingSubsteps(benchmark::State& st) {
  ring_substeps(st, false);
}
BENCHMARK(BM_RingSubsteps)
    ->ArgsProduct({{0, 1, 2}, {1, 2}})
    ->ArgNames({"case", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_RingSubstepsJohnsonCook(benchmark::State& st) {
  ring_substeps(st, true);
}
BENCHMARK(BM_RingSubstepsJohnsonCook)
    ->ArgsProduct({{0, 1, 2}, {1, 2}})
    ->ArgNames({"case", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_RingSubstepsJohnsonCookYielding(benchmark::State& st) {
  ring_substeps(st, true, 200.0);
}
BENCHMARK(BM_RingSubstepsJohnsonCookYielding)
    ->Args({0, 1})
    ->ArgNames({"case", "threads"})
    ->Iterations(100)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Calls of 20 sub-steps of b with the pair loops `loop`, timed; items = particle-sub-steps.
void time_substep_calls(benchmark::State& st, SolidBody& b, const Executor& exec,
                        SubstepPairLoop loop) {
  long substeps = 0;
  for (auto _ : st) {
    constexpr int kSteps = 20;
    run_elastic_substeps(b, kSteps, stable_time_step(b), {}, exec, SubstepSchedule::Auto, loop);
    substeps += kSteps;
  }
  st.SetItemsProcessed(substeps * static_cast<long>(b.size()));
  st.counters["particles"] = static_cast<double>(b.size());
  st.counters["pairs"] =
      static_cast<double>(b.topology.pairs.index.size()) / static_cast<double>(b.size());
}

// The scalar pair loops against the lanes, and a small body against a large one: the ring of
// case c advanced 20 sub-steps per call with the pair loops forced (loop 0: Auto, the lanes
// on an AVX-512F CPU; 1: Scalar). Case 3 (240 particles) against case 0 (2 514) gives the
// per-sub-step cost that does not grow with the body (none was found: app/cost_model.h, the
// comment of solid_lane_ns).
void BM_RingSubstepsPairLoop(benchmark::State& st) {
  SolidBody b = aluminium_ring(kRings[st.range(0)]);
  const SubstepPairLoop loop = st.range(1) == 1 ? SubstepPairLoop::Scalar : SubstepPairLoop::Auto;
  time_substep_calls(st, b, Executor(static_cast<int>(st.range(2))), loop);
}
BENCHMARK(BM_RingSubstepsPairLoop)
    ->ArgsProduct({{0, 3}, {0, 1}, {1}})
    ->ArgNames({"case", "loop", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The Eulerian path of failed particles (solid/eulerian_failed_interaction.h) against the
// Lagrangian one: the Johnson–Cook ring of case c with a sector of `permille`/1000 of its
// circumference failed at the start, 20 sub-steps per call. path 0: failed particles stay in
// the total-Lagrangian sums (`failed_particles = "lagrangian"`), scalar pair loops; 1: the
// same, the lanes (Auto); 2: switched (`failed_particles = "eulerian"`: the failed particles
// and their reference neighbours leave the TL sums and interact over current pairs rebuilt
// every sub-step; scalar loops, as every Eulerian body). Counter `switched`: the switched
// particles. Path 2 less path 0 per sub-step, at two switched counts, is the Eulerian path's
// cost per particle and per switched particle (app/cost_model.h eulerian_particle_ns,
// eulerian_switched_ns).
void BM_RingSubstepsEulerian(benchmark::State& st) {
  const double failed = 1e-3 * static_cast<double>(st.range(1));
  SolidBody b = aluminium_ring(kRings[st.range(0)], true, failed);
  const int path = static_cast<int>(st.range(2));
  b.eulerian_switch = path == 2;
  const SubstepPairLoop loop = path == 1 ? SubstepPairLoop::Auto : SubstepPairLoop::Scalar;
  const Executor exec(static_cast<int>(st.range(3)));
  // One step as a run takes it: the switch (path 2), its topology and f_int.
  double t = 0.0;
  const double dt0 = 20.0 * stable_time_step(b) * (1.0 - 1e-9);
  advance_body(b, t, dt0, {}, exec);
  t += dt0;
  time_substep_calls(st, b, exec, loop);
  st.counters["switched"] = static_cast<double>(b.eulerian.members.size());
}
BENCHMARK(BM_RingSubstepsEulerian)
    ->ArgsProduct({{0, 3}, {50, 200}, {0, 1, 2}, {1}})
    ->ArgNames({"case", "permille", "path", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
