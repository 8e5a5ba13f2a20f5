// The sub-step loop of an elastic body over one fluid step (spec §3; solid/body_dynamics.h
// for the integrator), fused: the operators of one sub-step — deformation gradient, the
// material law's committing update (exactly once per particle per sub-step,
// solid/stress_update.h), stress force, artificial viscosity, hourglass control, the kicks
// and the drift — run per particle in two passes over the pair lists, because two data
// dependencies cannot be avoided:
//   pass 1 (particle i): F_i and Ḟ_i need every neighbour's drifted position and half-step
//          velocity; then P_i (law), the stress power P̄:Ḟ/ρ0 and the hourglass moment G_i
//          with κ ε of i's pairs. The viscous pair terms depend on x and v½ only, so they
//          are computed here too, each pair once, by its lower particle, and stored for both
//          slots of the pair (the force on j is the exact negative of the force on i and the
//          heat the same number, so the per-particle sums below are those of
//          viscous_force_on bit for bit, at half the square roots and divisions);
//   pass 2 (particle i): the forces need V0_j P_j, G_j and κ ε of the reversed pairs of
//          every neighbour; stress, viscous and hourglass sums in one loop over i's pairs
//          (each in its own accumulator); then a_i, the second half kick, the internal energy,
//          i's powers for the energy bookkeeping and, for the next sub-step, the first half
//          kick and drift. Pass 2 reads no neighbour's x or v½, so the kick and drift update
//          them in place (with an Eulerian switch, whose pair forces read the neighbours'
//          current x and v½, into second buffers). f_av, f_hg, f_int, a and v are stored at
//          the last sub-step only: in between they live in registers and the per-particle
//          powers (memory traffic: the 60 000-particle ring does not fit in the caches).
// Each pass writes only its own particles' entries, apart from the viscous terms of pass 1,
// whose second slot (j, i) no other particle writes, so results are bit-identical for any
// thread count. The pair terms of i's own side in pass 2, V0_i P_i g_ij (stress) and
// G_i g_ij (hourglass), are summed as V0_i P_i Σ_j g_ij and G_i Σ_j g_ij with Σ_j g_ij per
// particle and call, and pass 1 stores V0_i P_i per particle, so the forces equal those of
// the standalone operators (tl_pair_force.h, artificial_viscosity.h, hourglass_control.h,
// deformation_gradient.h) to round-off, not bit for bit (tests/unit/test_solid_substep.cpp:
// relative 1e-12). The pair loops use two-lane vectors (core/simd2.h; F, Ḟ and G by
// columns), which round as the scalar forms. With a team of two or more threads the whole
// call is one parallel region with 2 barriers per sub-step, plus one after the first kick
// and drift (Executor::sync_counts). Reference pair constants in CSR order (g_ij, X_ij,
// hourglass stiffness κ_ij and viscous weight |c_ij| in one 48-byte record per pair for
// pass 1, j from the topology's index, the pair h and ρ0 from i's and j's; g_ji with j and
// the reverse slot in another for pass 2) are computed once per call, not per sub-step, so
// the pair loops read them without indirection; the loops are instantiated per law, per
// on/off state of hourglass control and viscosity and per Eulerian state
// (body.eulerian.active). The energy bookkeeping (dissipated, hourglass and external work)
// is summed serially in particle order, from the per-particle powers of pass 2: each thread
// continues, inside its pass 2, the chain that the thread before it carried to its share's
// start (of an earlier sub-step, one per rank; session 17), so it too does not depend on
// the thread count. All of this is bit-identical to the sub-step before these
// storage changes (docs/validation.md, "Solid sub-step").
// On CPUs with AVX-512F the two-pass schedule runs both passes' pair loops in eight lanes,
// one particle per lane, over a slot-major copy of the pair records
// (solid/substep_pair_lanes.h; session 18), then, for SVK, the law, the stress power and
// V0 P in the same lanes (solid/substep_law_lanes.h; session 19); other laws and the tails
// stay scalar; same bits.
// Two schedules run these per-particle steps (SubstepSchedule): the two-pass one above, and
// for large bodies without an Eulerian switch where the lanes do not run (session 19: the
// lanes are faster than the wavefront on 2 threads) a wavefront over the pair graph's levels
// (solid/substep_levels.h), which advances a band of ~2 × block levels through up to 20
// sub-steps while it is in the core's cache (2 barriers per block + 1 between blocks); the
// per-sub-step powers are then summed in particle order after each block. Same bits
// (tests/unit/test_solid_substep.cpp, docs/validation.md "Solid sub-step", session 15).
#pragma once
#include <cstddef>

#include "core/vec.h"
#include "solid/solid_body.h"

namespace slamsph {

class Executor;

// Particles per thread below which a body's sub-steps use fewer threads (a team of t threads
// needs at least t times this many particles): below it the barriers cost more than the split
// saves. With the bodies stored along the structure (geometry/structure_order.h) a team of
// two pays from 2 500 particles: cases/skin_ring_reduced.toml to 6 ms on 2 threads (passive
// waiting) took 13.4 s (median of 3) against 16.4 s with the former 4 000 (1 thread: 18.4 s;
// 2 threads next to a busy core: 18.2 s), results bit-identical (docs/model.md §5).
constexpr std::size_t kSubstepParticlesPerThread = 1000;

// Bodies of at least this many particles take the wavefront schedule of the sub-steps
// (elastic_substep.cpp) when it applies (no Eulerian switch, two or more sub-steps, a level
// structure narrow enough for the cache) and the two-pass schedule's pair loops in lanes do
// not (no AVX-512F, or calls of fewer than kMinLaneSubsteps sub-steps): where the lanes
// apply, the two-pass schedule with them is taken at any size (60 000-particle ring, 2
// threads: 1.18x the wavefront; docs/validation.md §6 "Solid sub-step", session 19).
// Smaller bodies take the two-pass schedule. All give the same bits.
constexpr std::size_t kSubstepWavefrontParticles = 20000;

// Bodies of at least this many particles whose sub-steps run the pair loops in lanes take
// them in the lagged sweep (elastic_substep.cpp: pass 2 a few chunks behind pass 1 in one
// sweep, so that it reads what pass 1 wrote from the cache): on the 60 000-particle ring
// it gains, on the 2 514-particle ring, whose arrays stay in the cache anyway, it cost
// ~8 % on 1 thread (docs/validation.md §6 "Solid sub-step", session 20). Same bits.
constexpr std::size_t kSubstepLaggedParticles = 20000;

// Which schedule runs the sub-steps: Auto (by the rules above) or one forced (tests,
// benchmarks); Wavefront still falls back to TwoPass where it does not apply, Lagged (the
// lanes' lagged sweep at any size) to TwoPass where the lanes do not run.
enum class SubstepSchedule { Auto, TwoPass, Wavefront, Lagged };

// `steps` sub-steps of size h [s] with the fluid force body.f_fluid and gravity g held; needs
// body.f_int of the current state (the first half kick). Leaves body.x, v, a, F, P, e, f_int,
// f_av, f_hg and the law's history at the end of the last sub-step and adds the sub-steps'
// dissipated, hourglass and external work to the body's accumulators.
// The passes' pair loops: Lanes takes the eight lanes (solid/substep_pair_lanes.h) in the
// two-pass schedule without an Eulerian switch where the CPU has AVX-512F, Scalar the scalar
// loops always (tests: the same bits), Auto the lanes for calls of at least
// kMinLaneSubsteps sub-steps: the set-up writes the pair records in the lanes' layout once
// per call, which a call of one sub-step does not win back (the oscillating plate, one
// sub-step per call: its solid phase 6.4 → 8.2-8.6 s with the lanes, docs/validation.md §6
// "Solid sub-step", session 18).
enum class SubstepPairLoop { Auto, Scalar, Lanes };
inline constexpr int kMinLaneSubsteps = 8;

void run_elastic_substeps(SolidBody& body, int steps, double h, Vec2 g, const Executor& exec,
                          SubstepSchedule schedule = SubstepSchedule::Auto,
                          SubstepPairLoop loop = SubstepPairLoop::Auto);

}  // namespace slamsph
