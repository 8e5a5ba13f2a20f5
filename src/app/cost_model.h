// Cost model of a run (issue 13 item 5), printed by `slamsph check`: from the built case
// (particle and pair counts, kernels, the initial state) it predicts the fluid step, the
// number of fluid steps and neighbour rebuilds to the end time, each elastic body's
// sub-steps per fluid step, the CPU time on one thread and the wall time on one and two
// threads, from costs measured on this machine kind (bench/calibrate_cost.py).
//
// Step prediction. The fluid step is the acoustic CFL step cfl h / (c0 + v) (spec §2) with
// v the larger of the initial speeds (water, bodies, prescribed motion tables) and the
// free-fall speed sqrt(2 g H) over the height H the water can fall: its highest particle
// above the lowest level some of it can reach, from the built geometry in columns two
// spacings wide across gravity — the water's top where it stands on a solid, the floor of a
// dry column or under a breach (debris holds no water). Still water falls nowhere (H = 0;
// with its whole depth the prediction had 15 % too many steps), a dam-break column by its
// height (the dry floor beside it), the water over a breached plate into the chamber below
// the slot (docs/validation.md §6 "Cost model", session 14); the initial acceleration bound
// C_a sqrt(h/|a|) if smaller
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
//             how much the measurements do not settle — docs/validation.md §6), times the
//             four-lane loop's fraction (0.59 → 0.70 over the same sizes) where that loop runs
//   lists   = c_rebuild (N_water + N_contact) per rebuild, one rebuild every s h_c / (v Δt)
//             steps (rebuilt when a particle has moved half the skin s 2 h_c,
//             coupling/interaction_lists.h; v the predicted speed)
//   contact = c_cpair P with water; c_dry N_contact without (body state, loads, and without
//             water also the step limit, checks and records). P is the mean of the listed
//             fluid–contact pairs (N_fc + N_cf) over the run: water that can fall spreads over
//             the dry floor of its container at about its fall speed, so the pairs go from
//             the initial count to the count at rest (the water spread over every column its
//             area reaches, to one level; in proportion to the surface contact particles
//             within the support that face the water) in (dry floor length) / sqrt(2 g H),
//             and stay there (the peer dam break's rose from 4 446 to ~10 000 in 1.3 s of its
//             6.4 s; predicted mean 8 592 against 9 639 measured; the elastic gate 19 240
//             against 22 151; cases/dam_break.toml 7 911 against 7 147)
//   solid   = Σ_elastic (c_sub n_b + c_call N_b + c_jc N_b n_b + c_yield N_b n_b f_y)
//             with n_b sub-steps per fluid step. c_sub: a call of at least kMinLaneSubsteps
//             sub-steps on an AVX-512F CPU runs both passes' pair loops in eight lanes
//             (solid/elastic_substep.cpp) and then costs per particle, c_lane N_b (session 20:
//             the 2-layer ring of BM_RingSubsteps, 3.0 pair entries per particle, and the
//             2 000-particle plate, 3.88, both 26 ns per particle-sub-step on one thread;
//             per pair entry the plate had measured 1.3x cheaper, and a probe of it put the
//             skins 15-22 % under their runs); shorter calls, other CPUs
//             and bodies with switched particles run the scalar loops, c_pair P_b per
//             sub-step over P_b pair
//             entries (each pair from both sides; the plate and the ring 18.0 and 16.8 ns per
//             entry before the lanes, session 13). c_sub log-linear in N_b between 25 000 and
//             60 000 particles, where the arrays leave the caches; 1.24x with water (the
//             water's arrays share the caches: whole runs against the body alone). c_call the
//             per-call set-up of the sub-step loop, solid/elastic_substep.cpp, per particle. c_jc
//             the Johnson–Cook law's elastic path per particle-sub-step, c_yield the return mapping
//             of a yielding particle, f_y the fraction of its particle-sub-steps that yield,
//             estimated from the body's loading (below); a body whose failed particles are
//             switched to the Eulerian path from the start (failed_particles = "eulerian",
//             particles failed at the start) c_eul N_b + c_sw N_sw more per sub-step with N_sw
//             switched particles (the switch made on a copy of the body as its first step will:
//             the built body has not made it; session 22, BM_RingSubstepsEulerian)
//   failure = c_fail N_b per fluid step once a body with failure has failed particles: every
//             gather of its state rebuilds a cell grid over the body, the normals near the
//             failed particles and the layers behind the crack faces (coupling/
//             contact_layout.cpp gather_body_state); in the contact phase
//   output  = c_snap per field snapshot within the run, c_profile more with the skin's
//             profile (drawn at a fixed size, on one thread; the fuselage sections' two
//             snapshots to 10 ms took ~1.1 s of 7.4)
// Yield and damage from the loading (Johnson–Cook bodies held by clamps; estimate_plastic in
// app/cost_model.cpp): the clamps' velocity against the free material's initial velocity
// Δv, against v_y = σ_y/(ρ c) the particle velocity an elastic wave can carry (c the
// plane-strain bar wave speed sqrt(E/((1-ν²)ρ)), σ_y the axial stress at which that wave
// yields, A/sqrt(1-ν+ν²)). Δv > v_y (an impact: the shipped Johnson–Cook bar, 150 m/s
// against 21 m/s): the material behind the elastic front yields as the front crosses it in
// L/c; the plastic strain at the clamp is von Kármán's (von Kármán & Duwez, J. Appl. Phys.
// 21 (1950) 987), Δv − v_y = ∫ sqrt(σ'(ε)/ρ) dε over the hardening A + B ε̄p^n; past the
// Johnson–Cook failure strain at the triaxiality of plane-strain tension (1/√3, without the
// rate and temperature terms) the body fails there within that crossing, and then only a band
// of two kernel supports at the failed section keeps yielding. Clamps moving apart at Δv
// over a gauge L (the notched specimen: 2 m/s over 30 mm) strain the material between them
// at Δv/L: it yields from ε_y/(Δv/L) on (ε_y = σ_y/E') and fails when its nominal plastic
// strain reaches the failure strain. Stress raisers (notches) and water loads are not seen:
// a body without clamps is costed elastic.
// The wall time on T threads divides the water, lists and contact phases by the measured
// two-thread speed-up S_f(N_water) (1 without water: those loops are too short to split) and
// each body's sub-steps by S_s(N_b) when its team has
// two threads (Executor::threads_for with kSubstepParticlesPerThread), 1 otherwise; when every
// elastic body's team has one thread, the water's pair pass takes min(S + P/S_f, max(S, P))
// with the sub-steps S (app/fsi_stepper.h: beside them or after them, whichever the run
// measures faster). This
// machine kind has two cores: T > 2 is predicted as T = 2.
#pragma once
#include <string>
#include <vector>

namespace slamsph {

class Simulation;

// Costs measured on the 2-core development machine (AMD EPYC, 1 MiB L2 per core, 32 MiB
// L3) with `bench/calibrate_cost.py build/slamsph --steps 60 --repeat 3` (each phase's CPU
// time in 1-thread runs of the shipped cases, fitted by least squares on the relative
// error; docs/validation.md §6 "Cost model" has the table and the machine's load). Refitted
// in session 18 on the code of that day (the lane loops of sessions 14-16, the fused sweeps
// and learnt splits of session 17), the 17 cases in three calls, idle: with the constants of
// session 10 the probes had measured this machine at x0.53-0.6 of them while its whole runs
// went at x0.7-1.0 (the water probe is mostly the pair pass, which the lanes made faster
// than the rest), and the peer dam break, the tension bar and the Johnson-Cook bar fell
// 28-39 % under their predictions on 2 threads. Session 20 measured the solid constants anew
// on this machine (the sub-step's pair loops and SVK law in AVX-512 lanes since sessions
// 18-19, the skins' ring as the probe; the Johnson–Cook law's, yield and failure costs from
// benchmarks and alternated runs; below).
// Two-thread speed-ups: docs/validation.md §6 (throughput.sh, BM_RingSubsteps, idle).
struct CostConstants {
  // Per listed water–water pair per fluid step, at ≤ water_n_small / ≥ water_n_large water
  // particles, as the scalar loop's (the session 18 fit with the lane fractions below taken
  // out: 5.07 and 7.38 ns measured in the lanes).
  double water_pair_ns_small = 8.6;
  double water_pair_ns_large = 12.4;
  double water_n_small = 3200, water_n_large = 166500;
  // The pair costs above were fitted on the scalar pair loop. The four-lane loop
  // (fluid/gsph_pair_band.h: Wendland kernel, CPUs with AVX2) takes this fraction of its time
  // (docs/validation.md §6 "Session 14", 1 thread, alternated runs: the peer dam break's
  // fluid rates 4.55-5.03 → 2.63-2.74 s at 3 200 water particles; skin_cylinder's to 2 ms
  // 2.01-2.55 → 1.58-1.63 s at 166 500), log-linear in between as the pair costs.
  double water_pair_lanes_small = 0.59, water_pair_lanes_large = 0.70;
  // The eight-lane loop (AVX-512F CPUs) against the four lanes (docs/validation.md §6
  // "Session 15", alternated runs on a loaded machine: the pass alone at 320 000 water
  // particles 32.8 against 38.5 ms of CPU on 1 thread, the 320 000-particle run's CPU 0.87x;
  // the 3 200-particle peer case the same within its noise), log-linear in between.
  double water_pair_eight_small = 1.0, water_pair_eight_large = 0.85;
  double water_ns = 14.5;         // per water particle per fluid step
  double rebuild_ns = 152.0;      // per water or contact particle per neighbour rebuild (the
                                  // fit counts the rebuilds of the steps, not the set-up's)
  double contact_pair_ns = 18.4;  // per listed fluid–contact pair (both lists) per fluid step
  // Per contact particle per fluid step, no water: every phase but the sub-steps (body state,
  // step limit, checks, records), from whole runs on 1 thread (session 18: the oscillating
  // plate 1.25 s over 31 557 steps of 1 872 particles, 21.2 ns; the tension bar 21.8 ns):
  // 60-step runs of these cases are mostly their first steps (the fit gave 68 ns).
  double dry_contact_ns = 22.0;
  // The solid constants below are this machine's (session 20, one thread, under quiet.py:
  // every other process paused), so that its probes measure about x1; the water constants
  // above are the session 18 fit's.
  // Per elastic particle per sub-step (SVK) in a call that runs the pair loops in lanes (at
  // least kMinLaneSubsteps sub-steps, AVX-512F, no Eulerian switch), ≤ solid_n_small
  // particles, the body alone: the probe ring (measure_machine_factors, the skins' 2-layer
  // ring, no hourglass control) x0.79-0.85 of 29 ns in the first round of session 20's table
  // = 23.5 ns; BM_RingSubsteps case 0 (the same ring with hourglass control and viscosity,
  // 20 sub-steps per call) 37.9-38.3 M particle-steps/s = 26.4 ns; the 2 000-particle plate
  // of session 18's probe (3.88 pair entries per particle against the ring's 3.0) 25.9 ns (its
  // factor x0.31 of 21.5 ns per entry): per particle, not per entry, in the lanes.
  // A small body pays no per-sub-step cost of its own on top (session 22,
  // BM_RingSubstepsPairLoop, one thread under quiet.py, medians of 5: the 240-particle ring
  // 40.7 M particle-steps/s in lanes and 29.1 M scalar against the 2 514-particle ring's 37.0
  // and 26.9 M, i.e. 8-9 % cheaper per particle, no fixed part): no constant for it.
  double solid_lane_ns = 23.5;
  // ≥ solid_n_large particles (log-linear between): the sub-step's arrays leave L2/L3.
  // Session 22, one thread under quiet.py, with the lagged sweep and the 2 MiB pages of
  // session 20 (bodies ≥ 20 000 particles): `bench_solid --benchmark_filter=
  // 'BM_RingSubsteps/case:[02]/threads:1' --benchmark_repetitions=5`, two calls, medians of 5:
  // the 60 000-particle ring (6 layers, 3.67 pair entries per particle) 20.3 and 17.6 M
  // particle-steps/s = 49.2 and 56.9 ns per particle-sub-step, against the 2 514-particle ring
  // (case 0) in the same calls 27.6 and 29.4 ns: 1.86x, taken on solid_lane_ns (was 26.2, the
  // ratio of session 18's per-entry constants, not measured with the lanes). No shipped case
  // has a body this large.
  double solid_lane_ns_large = 43.7;
  // Per elastic pair entry per sub-step (SVK) in the scalar pair loops (calls of fewer than
  // kMinLaneSubsteps sub-steps, CPUs without AVX-512F, Eulerian bodies), ≤ solid_n_small
  // particles: the probe ring's calls of 7 and of 1 sub-step (measure_machine_factors),
  // their difference over 6 sub-steps (session 20, three checks under quiet.py: x1.4-1.5 of a
  // trial 10 ns = 14.5 ns per entry, 43.5 ns per particle at the ring's 3.0 entries).
  double solid_pair_ns = 14.5;
  // ≥ solid_n_large particles, the same ratio as the lanes' (session 13: the 60 000-particle
  // ring 1.69x the 10 052 one per entry on one thread, 1.45-1.55x less with the wavefront of
  // session 15).
  double solid_pair_ns_large = 16.2;
  // The sub-steps in a run with water against the body alone (both pair loops): the water's
  // arrays share the caches with the body's between sub-step calls, and the body's state is
  // gathered and its fluid forces scattered. skin_cylinder to 10 ms on one thread (session
  // 20, quiet.py) 28.9 ns per particle-sub-step (4.84 s over 67 106 sub-steps of 2 500
  // particles), skin_L_floor_column 29.4 ns (14.13 s, 88 558 sub-steps of 5 434), against
  // the probe ring's 23.5: 1.24.
  double solid_wet_factor = 1.24;
  // Per elastic particle per call of the sub-step loop (its set-up, once per fluid step, twice
  // with the symplectic step): the probe ring's one-sub-step call less its scalar sub-step
  // (session 20, the same checks: x0.46-0.54 of a trial 50 ns = 25 ns); the tension bar's
  // solid phase (one sub-step per call, 3.79 entries per particle) 82 ns per particle and
  // call = 25 + 3.79 x 14.5. Scaled by its own machine factor.
  double solid_call_ns = 25.0;
  // The Eulerian path of failed particles (solid/eulerian_failed_interaction.h; a body with
  // failed_particles = "eulerian" and particles failed at the start, `[body.pre_failed]`)
  // beyond the scalar Lagrangian sub-step of the same body (whose pair loops it runs), per
  // sub-step: per particle of the body (the current pairs rebuilt every sub-step: a cell grid
  // over the switched particles searched from every particle, the counts and fills; the
  // Eulerian force's call per particle) and per switched particle (its velocity gradient,
  // F, stress map and pair forces over its current neighbours within 2h).
  // BM_RingSubstepsEulerian (bench/bench_solid.cpp: the Johnson–Cook rings with a sector failed at
  // the start, path 2 switched against path 0 kept in the total-Lagrangian sums, both scalar, 20
  // sub-steps per call), one thread under quiet.py, medians of 3 and of 5 in two calls
  // (session 22, `bench_solid --benchmark_filter=BM_RingSubstepsEulerian
  // --benchmark_repetitions=5`): per sub-step the 2 514-particle ring 69-77 µs more with 130
  // switched particles, 148-169 µs with 548; the 240-particle ring 5.7-7.3 µs with 16,
  // 14.3-15.8 µs with 56; fitted (least squares on the relative error) 15 ns per particle and
  // 205 ns per switched particle (the eight figures within −15/+22 %). The 240-particle ring's
  // Eulerian path against its Lagrangian one in lanes (path 1, what a run with
  // failed_particles = "lagrangian" takes): 1.45x with 16 switched, 1.80x with 56. Not
  // multiplied by solid_wet_factor (measured on the body alone, like the laws' terms);
  // scaled by the scalar loops' machine factor.
  double eulerian_particle_ns = 15.0;
  double eulerian_switched_ns = 205.0;
  // The Johnson–Cook law's elastic path per particle-sub-step beyond the SVK law (its return
  // mapping's yield test, the Mie–Grüneisen pressure, the heating and the damage update run
  // per particle, scalar, in either pair loop): BM_RingSubstepsJohnsonCook against
  // BM_RingSubsteps, case 0, one thread, medians of 3 (session 20): 10.6 against 37.9 M
  // particle-steps/s, 94.3 − 26.4 = 67.9 ns (x3.57 a lane sub-step; sessions 10-18 fitted
  // x2.56-2.98 per scalar pair entry).
  double johnson_cook_elastic_ns = 68.0;
  // A yielding Johnson–Cook particle-sub-step beyond an elastic one (the return mapping's
  // Newton iterations, the rate and heating terms): BM_RingSubstepsJohnsonCookYielding (the
  // same ring expanding at 200 m/s, 99 % of its particle-sub-steps yield) 2.03 M
  // particle-steps/s = 492 ns against the elastic ring's 94.3 ns, one thread, medians of 3
  // (session 20): (492 − 94) / 0.99 = 402 ns; at 100 m/s (62 % yielding) 17.0 against
  // 4.74 ms per 20 sub-steps, 394 ns. Charged per particle-sub-step at the yielding fraction
  // estimated from the loading (estimate_plastic, see the header comment).
  double johnson_cook_yield_ns = 400.0;
  // Per particle of a body with failed particles per fluid step (its gathers: a cell grid
  // over the body, the normals near the failed particles, the layers behind the crack
  // faces): cases/johnson_cook_bar.toml on one thread, alternated runs, 3 each (session 20):
  // contact phase 0.072 s with failure (first failure at 11.7 µs, 90 failed particles by the
  // end) against 0.018 s with `materials.al.failure = "none"`, over 1 530 steps of 1 050
  // particles from 11.7 µs of 150 µs: 36 ns.
  double failure_zone_ns = 36.0;
  // Per field snapshot (output.snapshots: the picture and its table, app/snapshots.h), and per
  // snapshot of the skin's profile (output.skin_profile) [s], whatever the run's threads and
  // nearly whatever its size (the picture is drawn at a fixed size): summary.json "other"
  // (set-up, records, output) of session 20's 2-thread runs under quiet.py, less ~0.05-0.1 s
  // without snapshots: cases/breached_plate.toml 1.0 s with 3 snapshots (0.32 s each),
  // cases/skin_ring_reduced.toml 1.75 s with 3 and the profile (0.58 s each: 33 250 water
  // particles), skin_cylinder to 2 ms with 2 and the profile 1.10-1.12 s (0.55 s each: 166 500
  // water particles). Not scaled: no probe measures output.
  double snapshot_s = 0.32, skin_profile_s = 0.24;
  // A symplectic fluid step (numerics.fluid_integrator, docs/model.md §5: a momentum and a
  // continuity pass) against a kick-drift-kick one, water and contact phases: dam break,
  // 7 131 steps either way, user CPU 12.5 against 9.1 s (docs/validation.md §6).
  double symplectic_step_factor = 1.38;
  // Two-thread speed-up of the water phases: small at ≤ n_small water particles, large at
  // ≥ n_large, log-linear between.
  double fluid_speedup_small = 1.56, fluid_speedup_large = 1.99;
  double fluid_n_small = 3200, fluid_n_large = 320000;
  // The solid cost holds its small-body value up to 25 000 particles: the 6-layer skin
  // (22 506 particles, session 12, docs/validation.md §6) ran its sub-steps at the 2-layer
  // skin's cost per pair entry; interpolating from 10 000 had predicted 1.47x more (the 5 ms
  // slice +59 %).
  double solid_n_small = 25000, solid_n_large = 60000;
  // Two-thread speed-up of a body's sub-steps whose team has two threads: small at
  // ≤ solid_speedup_n_small particles, large at ≥ solid_speedup_n_large, log-linear between.
  // Measured in whole-run slices, the solid phase on 1 and 2 threads: session 13 (each
  // against its own machine factor: docs/validation.md §6 "Cost model") the 2-layer skin
  // (2 500) 1.38, the L floor section (5 434) 1.47, the 6-layer skin (22 506) 1.79 and 2.03
  // in two pairs of slices (1.75 taken); the 60 000-particle ring of bench_solid 2.0. With
  // the lanes (session 20, under quiet.py, `slamsph run --end-time 0.01 --exact-threads`):
  // skin_cylinder 4.84 → 2.77 s (1.75), skin_L_floor_column 14.13 → 9.12 s (1.55): 1.65 taken
  // up to 2 500 particles.
  double solid_speedup_small = 1.65, solid_speedup_large = 1.75;
  double solid_speedup_n_small = 2500, solid_speedup_n_large = 22500;
};

struct BodyCost {
  std::string name;
  std::size_t particles = 0;
  std::size_t pairs = 0;  // elastic: its topology's pair entries (each pair from both sides)
  bool elastic = false;
  double stable_step = 0.0;    // [s] elastic: at the start; rigid: +inf
  long substeps_per_step = 0;  // elastic: per fluid step; rigid: 0
  bool lanes = false;          // elastic: its sub-steps' pair loops run in lanes
  bool johnson_cook = false;   // its law is Johnson–Cook (costed with yield and failure)
  // Particles on the Eulerian path from the first step (failed at the start, or next to a
  // failed one, with failed_particles = "eulerian"; solid/eulerian_failed_interaction.h).
  std::size_t switched = 0;
  // Johnson–Cook bodies, estimated from the loading (see the header comment): how it is
  // loaded ("impact", "clamps pulled apart", "no clamps": not estimated), the fraction of
  // its particle-sub-steps that yield, when it starts to yield and to fail [s] (+inf: not
  // within the run).
  std::string loading;
  double yield_fraction = 0.0;
  double yield_start = 0.0, damage_start = 0.0;
  double seconds = 0.0;          // elastic: predicted CPU seconds on one thread (sub-steps)
  double failure_seconds = 0.0;  // its failed particles' gathers (in the contact phase)
  double speedup = 1.0;          // elastic: its sub-steps' two-thread speed-up (1: one thread)
};

struct CostPrediction {
  std::size_t fluid_particles = 0;
  std::size_t contact_particles = 0;
  std::size_t water_pairs = 0;      // listed water–water pairs at the start (each once)
  std::size_t contact_pairs = 0;    // listed fluid→contact plus contact→fluid pairs
  double fall_height = 0.0;         // [m] the height the water can fall (the step's speed bound)
  double spread_seconds = 0.0;      // [s] the time the water takes to cover the dry floor (0: none)
  double contact_pairs_rest = 0.0;  // the contact pairs with the water at rest (spread)
  double contact_pairs_mean = 0.0;  // the predicted mean over the run (the contact phase's)
  std::vector<BodyCost> bodies;
  double speed = 0.0;       // the speed v of the step prediction [m/s]
  double dt = 0.0;          // predicted fluid step [s]
  std::string limiter;      // what sets it
  long fluid_steps = 0;     // to the end time
  long rebuilds = 0;        // neighbour-list rebuilds to the end time
  long solid_substeps = 0;  // over the run, all elastic bodies
  double fluid_seconds = 0.0, lists_seconds = 0.0, contact_seconds = 0.0, solid_seconds = 0.0;
  double water_pass_seconds = 0.0;  // the pair pass's part of fluid_seconds
  int snapshots = 0;                // field snapshots within the run
  double output_seconds = 0.0;      // their cost (one thread)
  double fluid_speedup = 1.0;       // of the water, lists and contact phases on two threads
  double cpu_seconds() const {
    return fluid_seconds + lists_seconds + contact_seconds + solid_seconds + output_seconds;
  }
  // Wall seconds on `threads` threads of an idle machine of this kind (two cores).
  double wall_seconds(int threads) const;
};

// The prediction for `sim` as constructed (time 0) to its end time.
CostPrediction predict_cost(const Simulation& sim, const CostConstants& k = {});

// This machine against the one the constants were measured on, from short built-in runs on
// one thread, each the fastest of five, divided by what `k` predicts for them: for the water
// phases, a 3 200-particle water block in a tank for 40 fluid steps; for the solid, the
// fuselage skins' body (a 2-layer aluminium ring, 0.6 m, 3 mm, 2 500 particles, 3.0 pair
// entries each) without water advanced by advance_body one sub-step per call (100 calls),
// 7 per call (20 calls: the scalar pair loops, under kMinLaneSubsteps) and 40 per call (5
// calls: the lanes). The 7-call less the 1-call is 6 scalar sub-steps (the scalar factor),
// the 40-call less the 1-call 39 sub-steps in lanes (the sub-step factor), the rest of the
// one-sub-step call its set-up (the call factor; session 18's probe, a 2 000-particle plate
// with 3.88 entries per particle, gained more from the lanes per entry than the skins: they
// came out 15-22 % under). A
// run whose bodies take hundreds of sub-steps per fluid step (the fuselage sections) costs
// almost only sub-steps, one that takes one per step (the oscillating plate) a set-up per
// sub-step, and the two do not change alike from machine to machine or from hour to hour (one
// factor for both, session 12, varied 0.64-0.95 and over-predicted the 6-layer skin by 86 %:
// docs/validation.md §6 "Cost model"). A CPU of another speed, or one whose sibling hardware
// thread is busy, changes the costs of each part alike to first order; `slamsph check` scales
// the constants by these factors (0.7-0.9 s on this machine kind, session 13).
struct MachineFactors {
  double fluid = 1.0;         // water, neighbour lists, contact
  double solid = 1.0;         // per sub-step in lanes
  double solid_scalar = 1.0;  // per sub-step in the scalar loops (and the laws' extra costs)
  double solid_call = 1.0;    // per call of the sub-step loop (its set-up)
};
MachineFactors measure_machine_factors(const CostConstants& k = {});
CostConstants scaled(const CostConstants& k, const MachineFactors& f);

// Several lines for `slamsph check`; the wall time for 1 and for `threads` threads.
std::string describe_cost(const CostPrediction& c, int threads);

}  // namespace slamsph
