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

// Reference constants of pair k = (i, j) read by pass 1 (F, Ḟ, hourglass moment), in one
// record so that the pass streams one array; j comes from the topology's index. 24 bytes:
// what is formed exactly from per-particle arrays is not stored per pair (j is near i in the
// stored order, so its entries are in cache): X_j − X_i from X, the pair smoothing length
// and density of the viscous term from h and ρ0; the viscous weight is per pair, not per
// slot (SubstepWorkspace::viscous_weight).
struct SubstepPairRef {
  Vec2 g;        // g_ij = topology.grad0[k] [1/m]
  double kappa;  // hourglass pair stiffness κ_ij [N/m^3·m^2]
};
// Those read by pass 2 (forces).
struct SubstepPairRev {
  Vec2 g_rev;  // g_ji = topology.grad0[pair_reverse[k]] [1/m]
  std::uint32_t j;
  std::uint32_t reverse;
};
// Viscous pair term of the current sub-step, of pair (i, j) with i < j: force on i from j
// (on j from i: −f) and the heating rate of each of the two particles from the pair [W/m].
struct SubstepViscous {
  Vec2 f;
  double q = 0.0;
};
// Per particle, gathered by the neighbours in pass 2: V0 P (the stress of the TL pair force)
// and the hourglass moment G, each by columns (c0 = (xx, yx), c1 = (xy, yy)).
struct SubstepParticleMats {
  Vec2 vp_c0, vp_c1, g_c0, g_c1;
};

// Per particle, the powers of the energy bookkeeping of one sub-step, written in pass 2 and
// summed in particle order by the team's first thread during the next pass 1 (the forces and
// velocities they come from are overwritten meanwhile) [W/m]: f_av·v, f_hg·v, f_ext·v½ and
// for a clamped particle (f_int + f_ext)·v_clamp.
struct SubstepPower {
  double viscous, hourglass, external, clamp;
};

struct SubstepWorkspace {
  // Per pair k = (i, j), in the topology's CSR order: reference constants, filled at the
  // start of every call (so a rebuilt topology needs no invalidation), read in the pair
  // loops without the indirections through pair_reverse, X and the per-particle h and ρ0.
  std::vector<SubstepPairRef> ref;
  std::vector<SubstepPairRev> rev;
  // Per pair, of the current sub-step.
  std::vector<Vec2> keps;  // κ_ij ε_ij (hourglass)
  // Once per pair {i, j}, not per slot (the lower particle's term serves both), at u = k −
  // lower[i] for the slot k of i's row with j > i: the slots with j > i in CSR order. Pass 1
  // streams them, pass 2 reads i's own ones in order and those of its pairs with j < i, at
  // slot reverse[k] of j's row, from the rows of the nearby j.
  std::vector<double> viscous_weight;   // |c_ij| of the artificial viscosity, per call [m]
  std::vector<SubstepViscous> viscous;  // viscous pair terms
  // Per particle.
  std::vector<std::uint32_t> upper;           // first k of i's row with j > i (rows are sorted)
  std::vector<std::uint32_t> lower;           // slots with j < i in the rows 0..i (lower slots)
  std::vector<std::uint32_t> lower_in_share;  // per thread of the team: its rows' lower slots
  std::vector<Vec2> gsum;                     // Σ_j g_ij over i's pairs, per call [1/m]
  std::vector<SubstepParticleMats> mats;      // V0 P and G by columns
  std::vector<Vec2> fext;                     // fluid force + weight, held over the call [N/m]
  std::vector<SubstepPower> power;            // of the sub-step just completed
  std::vector<Vec2> vhalf;                    // half-step velocity
  // With an Eulerian switch only (otherwise updated in place): v½ and x after the next kick
  // and drift, swapped with vhalf and body.x after pass 2.
  std::vector<Vec2> vhalf_next;
  std::vector<Vec2> x_next;
  std::vector<double> stress_power;  // P̄ : Ḟ / ρ0 of the sub-step [W/kg]
  std::vector<Mat2> P_kin;           // P Cᵀ after an Eulerian switch (SolidBody::kinematic_P)

  void resize(std::size_t particles, std::size_t pairs, std::size_t threads) {
    ref.resize(pairs);
    rev.resize(pairs);
    keps.resize(pairs);
    // Every pair is stored from both sides (topology.pair_reverse), so pairs / 2 of them.
    viscous_weight.resize(pairs / 2);
    viscous.resize(pairs / 2);
    upper.resize(particles);
    lower.resize(particles);
    lower_in_share.resize(threads);
    stress_power.resize(particles);
    gsum.resize(particles);
    mats.resize(particles);
    fext.resize(particles);
    power.resize(particles);
    vhalf.resize(particles);
  }
};

}  // namespace slamsph
