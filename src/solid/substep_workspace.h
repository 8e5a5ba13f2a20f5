// Storage of the fused elastic sub-step (solid/elastic_substep.h), kept in the body so that
// the sub-step loop never allocates (vectors are resized once per fluid step, a no-op while
// the sizes stay). Not state: derived per call from the topology, the material and the
// body's fields; never persistent, never written out.
#pragma once
#include <cstddef>
#include <vector>

#include "core/vec.h"

namespace slamsph {

struct SubstepWorkspace {
  // Per pair (reference constants, filled at the start of every call, so a rebuilt topology
  // needs no invalidation).
  std::vector<double> kappa;           // hourglass pair stiffness κ_ij [N/m^3·m^2]
  std::vector<double> viscous_weight;  // |c_ij| of the artificial viscosity [m]
  std::vector<Vec2> keps;              // κ_ij ε_ij of the current sub-step
  // Per particle.
  std::vector<Mat2> G;      // hourglass moment Σ_j κ ε ⊗ X_ij
  std::vector<Vec2> fext;   // fluid force + weight, held over the call [N/m]
  std::vector<Vec2> vhalf;  // half-step velocity (two buffers, swapped)
  std::vector<Vec2> vhalf_next;
  std::vector<Vec2> x_next;          // positions after the next drift (swapped with body.x)
  std::vector<double> stress_power;  // P̄ : Ḟ / ρ0 of the sub-step [W/kg]

  void resize(std::size_t particles, std::size_t pairs) {
    kappa.resize(pairs);
    viscous_weight.resize(pairs);
    keps.resize(pairs);
    G.resize(particles);
    fext.resize(particles);
    vhalf.resize(particles);
    vhalf_next.resize(particles);
    x_next.resize(particles);
    stress_power.resize(particles);
  }
};

}  // namespace slamsph
