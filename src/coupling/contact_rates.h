// The two halves of the fluid–solid contact (spec §4), evaluated gather-style:
//  - add_contact_to_fluid: each fluid particle adds its solid neighbours' pressure
//    force, viscous force and continuity term (solid velocity through v*).
//  - compute_contact_reaction: each solid particle sums minus the same pair forces.
// Both call contact_pair() with identical arguments, so sum of the two is zero to round-off.
// `pass` (fluid_integrator_kind.h): Momentum adds only the forces to a, Continuity only the
// density term to drho; the reaction belongs to the momentum sums (call it with those).
#pragma once
#include "core/cell_grid.h"
#include "core/kernel.h"
#include "core/parallel.h"
#include "coupling/contact_particles.h"
#include "fluid/fluid_integrator_kind.h"
#include "fluid/fluid_particles.h"

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

void add_contact_to_fluid(FluidParticles& f, const ContactParticles& c, const NeighbourList& fc,
                          const Kernel& kernel, const ContactParams& prm, const Executor& exec,
                          RatePass pass = RatePass::Both);

void compute_contact_reaction(ContactParticles& c, const FluidParticles& f, const NeighbourList& cf,
                              const Kernel& kernel, const ContactParams& prm, const Executor& exec);

}  // namespace slamsph
