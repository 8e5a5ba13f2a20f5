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
//   pass 2 (particle i): the forces need P_j, G_j and κ ε of the reversed pairs of every
//          neighbour; stress, viscous and hourglass sums in one loop over i's pairs (each in
//          its own accumulator and order); then a_i, the second half kick, the internal
//          energy and, for the next sub-step, the first half kick and drift into second
//          buffers (neighbours still read the current x and v½ in this pass).
// Each pass writes only its own particles' entries, apart from the viscous terms of pass 1,
// whose second slot (j, i) no other particle writes; results are bit-identical to the
// standalone operators' sequence (tl_pair_force.h, artificial_viscosity.h,
// hourglass_control.h, deformation_gradient.h; tests/unit/test_solid_substep.cpp) and for
// any thread count. With a team of two or more threads the whole call is one parallel region
// with 2 barriers per sub-step, plus one after the first kick and drift
// (Executor::sync_counts). Reference pair constants in CSR order (hourglass stiffness κ_ij,
// viscous weight |c_ij|, pair h and ρ0, X_ij, the reverse gradient g_ji) are computed once
// per call, not per sub-step, so the pair loops read them without indirection; the loops
// are instantiated per law and per on/off state of hourglass control and viscosity. The
// energy bookkeeping (dissipated, hourglass and external work) is summed serially in
// particle order by the team's first thread while the others run pass 1 of the next
// sub-step, so it too does not depend on the thread count.
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

// `steps` sub-steps of size h [s] with the fluid force body.f_fluid and gravity g held; needs
// body.f_int of the current state (the first half kick). Leaves body.x, v, a, F, P, e, f_int,
// f_av, f_hg and the law's history at the end of the last sub-step and adds the sub-steps'
// dissipated, hourglass and external work to the body's accumulators.
void run_elastic_substeps(SolidBody& body, int steps, double h, Vec2 g, const Executor& exec);

}  // namespace slamsph
