// The two halves of the fluid–solid contact (spec §4), evaluated gather-style:
//  - add_contact_to_fluid: each fluid particle adds its solid neighbours' pressure
//    force, viscous force and continuity term (solid velocity through v*).
//  - compute_contact_reaction: each solid particle sums minus the same pair forces.
// Both call contact_pair() with identical arguments, so sum of the two is zero to round-off;
// given the pair forces the fluid's sum kept (ContactPairForces), the reaction subtracts
// those instead of evaluating the pairs again (the same bits, half the pair evaluations).
// `pass` (fluid_integrator_kind.h): Momentum adds only the forces to a, Continuity only the
// density term to drho; the reaction belongs to the momentum sums (call it with those).
#pragma once
#include <cstdint>
#include <vector>

#include "core/cell_grid.h"
#include "core/kernel.h"
#include "core/parallel.h"
#include "coupling/contact_particles.h"
#include "fluid/fluid_integrator_kind.h"
#include "fluid/fluid_particles.h"
#include "fluid/gsph_fluid_rates.h"

namespace slamsph {

struct ContactParams {
  double c0 = 0.0;
  double omega = 3.0;
  double viscosity = 0.0;  // kinematic [m^2/s]; no-slip viscous term only if > 0
  Vec2 gravity;            // [m/s^2], for the static state in the Riemann U* (riemann_solver.h)
  // Lowest star pressure before the water separates (FluidConfig::cavitation_pressure).
  double cavitation_pressure = -101325.0;
  bool hydrostatic_correction = true;  // static state (g - a_s) . r in U*; false: none
  // Stiffness of the short-range barrier (contact_pair.h, contact_barrier_force) [Pa]; 0 = off.
  double barrier_pressure = 0.0;
};

// The pair forces of the last add_contact_to_fluid with a momentum sum, per entry of fc: the
// force on the fluid particle (pressure + barrier + viscous, and the viscous part alone) of
// every pair that acted. compute_contact_reaction given them (and cf's entries in fc,
// InteractionLists::cf_in_fc) subtracts these instead of evaluating each pair a second time:
// the same values in the same order, so the same sums bit for bit.
struct ContactPairForces {
  std::vector<Vec2> total, viscous;
  std::vector<std::uint8_t> acted;
};

// `loop` as for the fluid's pass (gsph_fluid_rates.h, PairLoop): Auto takes the contact's
// eight- or four-lane loop (coupling/contact_pair_lanes.h) for the Wendland kernel where the CPU
// has it, Scalar the scalar loop; all give the same bits.
void add_contact_to_fluid(FluidParticles& f, const ContactParticles& c, const NeighbourList& fc,
                          const Kernel& kernel, const ContactParams& prm, const Executor& exec,
                          RatePass pass = RatePass::Both, ContactPairForces* keep = nullptr,
                          PairLoop loop = PairLoop::Auto);

// With `kept` and `cf_in_fc` the forces kept by add_contact_to_fluid for the same state.
void compute_contact_reaction(ContactParticles& c, const FluidParticles& f, const NeighbourList& cf,
                              const Kernel& kernel, const ContactParams& prm, const Executor& exec,
                              const ContactPairForces* kept = nullptr,
                              const std::vector<std::uint32_t>* cf_in_fc = nullptr);

}  // namespace slamsph
