// Cost model of a run (issue 13 item 5), printed by `slamsph check`: from the built case
// (particle and pair counts, kernels, the initial state) it predicts the fluid step, the
// number of fluid steps and neighbour rebuilds to the end time, each elastic body's
// sub-steps per fluid step, the CPU time on one thread and the wall time on one and two
// threads, from costs measured on this machine kind (bench/calibrate_cost.py).
//
// Step prediction. The fluid step is the acoustic CFL step cfl h / (c0 + v) (spec §2) with
// v the larger of the initial speeds (water, bodies, prescribed motion tables) and the
// free-fall speed sqrt(2 g H) over the water's height H, which the water reaches wherever
// it collapses or is displaced; the initial acceleration bound C_a sqrt(h/|a|) if smaller
// (app/time_step_limit.h). Elastic bodies take ceil(Δt/Δt_s) sub-steps (their stable step
// at the start, solid/body_dynamics.h); when bodies share the step (dual time stepping off,
// or no water) the step is the smallest stable step and every body takes one sub-step. Not
// predicted: impacts that raise the fluid acceleration bound, bodies that speed up. With the
// symplectic fluid step the bodies take two halves per step, 2 ceil((Δt/2)/Δt_s) sub-steps,
// and the water and contact phases cost symplectic_step_factor times more per step.
//
// Cost, per fluid step (CPU seconds on one thread; the phases of app/phase_times.h):
//   water   = c_pair(N_water) N_ff + c_water N_water  (GSPH pair pass over the listed pairs,
//             Verlet skin included; integration, limits, checks). c_pair is log-linear in
//             N_water between its values at 3 200 and 166 500 particles (fitted 11.8 and
//             20.6 ns under load, 16.3 and 19.0 ns in an idle repeat: a rise with size, by
//             how much the measurements do not settle — docs/validation.md §6)
//   lists   = c_rebuild (N_water + N_contact) per rebuild, one rebuild every s h_c / (v Δt)
//             steps (rebuilt when a particle has moved half the skin s 2 h_c,
//             coupling/interaction_lists.h; v the predicted speed)
//   contact = c_cpair (N_fc + N_cf) with water; c_dry N_contact without (body state, loads)
//   solid   = Σ_elastic N_b (k_law c_sub(N_b) n_b + c_call) (n_b sub-steps per fluid step;
//             c_call the per-call set-up of the sub-step loop, solid/elastic_substep.cpp;
//             c_sub log-linear in N_b between 25 000 and 60 000 particles, cache again)
// The wall time on T threads divides the water, lists and contact phases by the measured
// two-thread speed-up S_f(N_water) and each body's sub-steps by S_s(N_b) when its team has
// two threads (Executor::threads_for with kSubstepParticlesPerThread), 1 otherwise. This
// machine kind has two cores: T > 2 is predicted as T = 2.
#pragma once
#include <string>
#include <vector>

namespace slamsph {

class Simulation;

// Costs measured on the 2-core development machine (AMD EPYC, 1 MiB L2 per core, 32 MiB
// L3) with `bench/calibrate_cost.py build/slamsph --steps 60 --repeat 3` (each phase's CPU
// time in 1-thread runs of the shipped cases, fitted by least squares on the relative
// error; docs/validation.md §6 "Cost model" has the table and the machine's load).
// Two-thread speed-ups: docs/validation.md §6 (throughput.sh, BM_RingSubsteps, idle).
struct CostConstants {
  double water_pair_ns_small = 11.8;  // per listed water–water pair per fluid step, at
  double water_pair_ns_large = 20.6;  // ≤ water_n_small / ≥ water_n_large water particles
  double water_n_small = 3200, water_n_large = 166500;
  double water_ns = 21.4;         // per water particle per fluid step
  double rebuild_ns = 157.0;      // per water or contact particle per neighbour rebuild
  double contact_pair_ns = 33.2;  // per listed fluid–contact pair (both lists) per fluid step
  double dry_contact_ns = 12.0;   // per contact particle per fluid step, no water
  double solid_ns = 100.0;        // per elastic particle per sub-step (SVK), ≤ solid_n_small
  // ≥ solid_n_large particles (log-linear between): the sub-step's arrays leave L2/L3 — the
  // 60 000-particle ring of bench_solid runs 2.05x slower per particle than the 10 052 one
  // (BM_RingSubsteps, 1 thread, idle, medians of 3: 303 against 148 ns, docs/validation.md
  // §6).
  double solid_ns_large = 205.0;
  // Per elastic particle per fluid step (the sub-step loop's set-up): the two fits gave 8 and
  // 140 ns (poorly determined by 60-step runs); 60 ns reproduces the one-sub-step-per-step
  // cases (oscillating plate, tension bar: 90–239 and 132–226 ns per particle-step measured).
  double solid_call_ns = 60.0;
  double johnson_cook_factor = 2.56;  // a Johnson–Cook sub-step against an SVK one
  // A symplectic fluid step (numerics.fluid_integrator, docs/model.md §5: a momentum and a
  // continuity pass) against a kick-drift-kick one, water and contact phases: dam break,
  // 7 131 steps either way, user CPU 12.5 against 9.1 s (docs/validation.md §6).
  double symplectic_step_factor = 1.38;
  // Two-thread speed-up of the water phases: small at ≤ n_small water particles, large at
  // ≥ n_large, log-linear between.
  double fluid_speedup_small = 1.56, fluid_speedup_large = 1.99;
  double fluid_n_small = 3200, fluid_n_large = 320000;
  // Two-thread speed-up of a body's sub-steps whose team has two threads: likewise.
  double solid_speedup_small = 1.35, solid_speedup_large = 1.64;
  // The solid cost and speed-up hold their small-body values up to 25 000 particles: the
  // 6-layer skin (22 506 particles, session 12, docs/validation.md §6) ran its sub-steps at
  // 60 ns per particle-sub-step on 1 thread (94 ns before the machine factor, against the
  // fitted 100) and 1.32x faster on 2 threads; interpolating from 10 000 had predicted
  // 138 ns and 1.47x (the 5 ms slice +59 %).
  double solid_n_small = 25000, solid_n_large = 60000;
};

struct BodyCost {
  std::string name;
  std::size_t particles = 0;
  bool elastic = false;
  double stable_step = 0.0;    // [s] elastic: at the start; rigid: +inf
  long substeps_per_step = 0;  // elastic: per fluid step; rigid: 0
  double law_factor = 1.0;     // sub-step cost of its material law relative to SVK
  double seconds = 0.0;        // elastic: predicted CPU seconds on one thread
  double speedup = 1.0;        // elastic: its sub-steps' two-thread speed-up (1: one thread)
};

struct CostPrediction {
  std::size_t fluid_particles = 0;
  std::size_t contact_particles = 0;
  std::size_t water_pairs = 0;    // listed water–water pairs at the start (each once)
  std::size_t contact_pairs = 0;  // listed fluid→contact plus contact→fluid pairs
  std::vector<BodyCost> bodies;
  double speed = 0.0;       // the speed v of the step prediction [m/s]
  double dt = 0.0;          // predicted fluid step [s]
  std::string limiter;      // what sets it
  long fluid_steps = 0;     // to the end time
  long rebuilds = 0;        // neighbour-list rebuilds to the end time
  long solid_substeps = 0;  // over the run, all elastic bodies
  double fluid_seconds = 0.0, lists_seconds = 0.0, contact_seconds = 0.0, solid_seconds = 0.0;
  double fluid_speedup = 1.0;  // of the water, lists and contact phases on two threads
  double cpu_seconds() const {
    return fluid_seconds + lists_seconds + contact_seconds + solid_seconds;
  }
  // Wall seconds on `threads` threads of an idle machine of this kind (two cores).
  double wall_seconds(int threads) const;
};

// The prediction for `sim` as constructed (time 0) to its end time.
CostPrediction predict_cost(const Simulation& sim, const CostConstants& k = {});

// This machine against the one the constants were measured on: the CPU time of two short
// built-in runs on one thread (a 3 200-particle water block in a tank, 40 fluid steps; a
// 2 000-particle SVK plate without water, 60 steps), each the fastest of three, divided by
// what `k` predicts for them. A CPU of another speed, or one whose sibling hardware thread
// is busy, changes all costs alike to first order; `slamsph check` scales the constants by
// these factors (about 0.3 s). Measured: 1 on the calibration runs' machine by
// construction of the fit; 0.4–0.6 on the same machine kind when it is idle (docs/validation.md
// §6 "Cost model").
struct MachineFactors {
  double fluid = 1.0;  // water, neighbour lists, contact
  double solid = 1.0;  // sub-steps
};
MachineFactors measure_machine_factors(const CostConstants& k = {});
CostConstants scaled(const CostConstants& k, const MachineFactors& f);

// Several lines for `slamsph check`; the wall time for 1 and for `threads` threads.
std::string describe_cost(const CostPrediction& c, int threads);

}  // namespace slamsph
