// Cost model of a run (issue 13 item 5), printed by `slamsph check`: from the built case
// (particle counts, kernels, the initial state) it predicts the fluid step, the number of
// fluid steps to the end time, each elastic body's sub-steps per fluid step and the CPU
// time on one thread, from per-particle costs measured on the development machine.
//
// Step prediction. The fluid step is the acoustic CFL step cfl h / (c0 + v) (spec §2) with
// v the larger of the initial speeds (water, bodies, prescribed motion tables) and the
// free-fall speed sqrt(2 g H) over the water's height H, which the water reaches wherever
// it collapses or is displaced; the initial acceleration bound 0.25 sqrt(h/|a|) if smaller
// (app/time_step_limit.h). Elastic bodies take ceil(Δt/Δt_s) sub-steps (their stable step
// at the start, solid/body_dynamics.h); when bodies share the step (dual time stepping off,
// or no water) the step is the smallest stable step and every body takes one sub-step. Not
// predicted: impacts that raise the fluid acceleration bound, bodies that speed up.
//
// Cost = steps × (N_fluid c_fluid + N_contact c_contact) + Σ_elastic steps × k × N c_solid.
#pragma once
#include <string>
#include <vector>

namespace slamsph {

class Simulation;

// CPU nanoseconds per particle and step on one thread. Measured 2026-11-29 on the 2-core
// development machine (shared, load ~24; user CPU time, so the load inflates them little):
//  - fluid and contact: `/usr/bin/time -f %U slamsph run CASE --no-output -q --threads 1
//    --max-steps 1500` on cases/still_water.toml (5 000 water, 992 wall particles: 1.04 ms
//    per step) and bench/dam_break_peer.toml (3 200 water, 2 612 wall: 0.887 ms per step),
//    medians of 3, solved for the two unknowns;
//  - solid: bench_solid BM_RingSubsteps case 0 and 1, 1 thread, CPU column (72 and 85 ns
//    per particle-sub-step, SVK with viscosity and hourglass control). Measured before the
//    sub-step of branch solidfast, which takes 1.45–1.47x fewer instructions
//    (docs/validation.md §6): to be measured again on an idle machine.
//  - the Johnson–Cook law's sub-step costs johnson_cook_factor times an SVK one: callgrind
//    instruction ratio of bench_solid BM_RingSubstepsJohnsonCook to BM_RingSubsteps, 1.71 /
//    1.65 / 1.64 at 2 514 / 10 052 / 60 000 particles on the elastic path (docs/validation.md
//    §6); a yielding particle costs more (the Newton iteration), not modelled. J2 is taken at
//    the SVK cost (not measured).
struct CostConstants {
  double fluid_ns = 186.0;    // per water particle per fluid step
  double contact_ns = 112.0;  // per contact (body surface and ghost) particle per fluid step
  double solid_ns = 80.0;     // per elastic particle per sub-step (SVK)
  double johnson_cook_factor = 1.65;
};

struct BodyCost {
  std::string name;
  std::size_t particles = 0;
  bool elastic = false;
  double stable_step = 0.0;    // [s] elastic: at the start; rigid: +inf
  long substeps_per_step = 0;  // elastic: per fluid step; rigid: 0
  double law_factor = 1.0;     // sub-step cost of its material law relative to SVK
};

struct CostPrediction {
  std::size_t fluid_particles = 0;
  std::size_t contact_particles = 0;
  std::vector<BodyCost> bodies;
  double speed = 0.0;       // the speed v of the step prediction [m/s]
  double dt = 0.0;          // predicted fluid step [s]
  std::string limiter;      // what sets it
  long fluid_steps = 0;     // to the end time
  long solid_substeps = 0;  // over the run, all elastic bodies
  double fluid_seconds = 0.0, contact_seconds = 0.0, solid_seconds = 0.0;
  double cpu_seconds() const { return fluid_seconds + contact_seconds + solid_seconds; }
};

// The prediction for `sim` as constructed (time 0) to its end time.
CostPrediction predict_cost(const Simulation& sim, const CostConstants& k = {});

// Several lines for `slamsph check`.
std::string describe_cost(const CostPrediction& c);

}  // namespace slamsph
