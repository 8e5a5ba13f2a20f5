// Storage of the fused elastic sub-step (solid/elastic_substep.h), kept in the body so that
// the sub-step loop never allocates (vectors are resized once per fluid step, a no-op while
// the sizes stay). Not state: derived per call from the topology, the material and the
// body's fields; never persistent, never written out.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/vec.h"

namespace slamsph {

struct SubstepWorkspace {
  // Per pair k = (i, j), in the topology's CSR order: reference constants, filled at the
  // start of every call (so a rebuilt topology needs no invalidation), read in the pair
  // loops without the indirections through pair_reverse, X and the per-particle h and ρ0.
  std::vector<double> kappa;           // hourglass pair stiffness κ_ij [N/m^3·m^2]
  std::vector<double> viscous_weight;  // |c_ij| of the artificial viscosity [m]
  std::vector<double> pair_h;          // symmetric smoothing length (h_i + h_j)/2 [m]
  std::vector<double> pair_rho0;       // (ρ0_i + ρ0_j)/2 [kg/m^3]
  std::vector<Vec2> X_ij;              // X_j − X_i [m]
  std::vector<Vec2> g_rev;             // g_ji = topology.grad0[pair_reverse[k]] [1/m]
  // Per pair, of the current sub-step.
  std::vector<Vec2> keps;      // κ_ij ε_ij (hourglass)
  std::vector<Vec2> f_visc;    // viscous pair force on i from j (−f_visc of the reverse pair)
  std::vector<double> q_visc;  // heating rate of each particle from the pair [W/m]
  // Per particle.
  std::vector<std::uint32_t> upper;  // first k of i's row with j > i (rows are sorted)
  std::vector<Mat2> G;               // hourglass moment Σ_j κ ε ⊗ X_ij
  std::vector<Vec2> fext;            // fluid force + weight, held over the call [N/m]
  std::vector<Vec2> vhalf;           // half-step velocity (two buffers, swapped)
  std::vector<Vec2> vhalf_next;
  std::vector<Vec2> x_next;          // positions after the next drift (swapped with body.x)
  std::vector<double> stress_power;  // P̄ : Ḟ / ρ0 of the sub-step [W/kg]
  std::vector<Mat2> P_kin;           // P Cᵀ after an Eulerian switch (SolidBody::kinematic_P)

  void resize(std::size_t particles, std::size_t pairs) {
    kappa.resize(pairs);
    viscous_weight.resize(pairs);
    pair_h.resize(pairs);
    pair_rho0.resize(pairs);
    X_ij.resize(pairs);
    g_rev.resize(pairs);
    keps.resize(pairs);
    f_visc.resize(pairs);
    q_visc.resize(pairs);
    upper.resize(particles);
    G.resize(particles);
    fext.resize(particles);
    vhalf.resize(particles);
    vhalf_next.resize(particles);
    x_next.resize(particles);
    stress_power.resize(particles);
  }
};

}  // namespace slamsph
