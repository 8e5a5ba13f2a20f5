// Storage of the fused elastic sub-step (solid/elastic_substep.h), kept in the body so that
// the sub-step loop never allocates (vectors are resized once per fluid step, a no-op while
// the sizes stay). Not state: derived per call from the topology, the material and the
// body's fields; never persistent, never written out.
//
// The 60 000-particle ring of bench/bench_solid.cpp does not fit in the last-level cache, so
// the sub-step is bound by the bytes it streams: nothing is stored per pair or per particle
// that the passes can form exactly from what they read anyway. The pair loops read the
// topology's CSR arrays directly: pass 1 g_ij = grad0[k] and j = index[k] in order, pass 2
// g_ji = grad0[pair_reverse[k]] from the rows of the nearby j (j is near i in the stored
// order, so those rows are in cache); X_j − X_i is formed from X, the pair smoothing length
// and density of the viscous term from h and ρ0 (the body's when uniform).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/vec.h"

namespace slamsph {

// Viscous pair term of the current sub-step, of pair (i, j) with i < j: force on i from j
// (on j from i: −f) and the heating rate of each of the two particles from the pair [W/m].
struct SubstepViscous {
  Vec2 f;
  double q = 0.0;
};
// Per particle, written in pass 1 and gathered by the neighbours in pass 2: the stress of the
// TL pair force (P, or P Cᵀ after an Eulerian switch; pass 2 multiplies it by V0, which
// rounds as V0 P) and the hourglass moment G, each by columns (c0 = (xx, yx), c1 = (xy,
// yy)). Without an Eulerian switch this P is also the next sub-step's P_old, so body.P is
// stored at the last sub-step of a call only.
struct SubstepParticleMats {
  Vec2 p_c0, p_c1, g_c0, g_c1;
};

// Per particle, the powers of the energy bookkeeping of one sub-step, written in pass 2 and
// summed in particle order by the team's first thread during the next pass 1 (the forces and
// velocities they come from are overwritten meanwhile) [W/m]: f_av·v, f_hg·v, f_ext·v½; for
// a clamped particle (f_int + f_ext)·v_clamp in SubstepWorkspace::clamp_power.
struct SubstepPower {
  double viscous, hourglass, external;
};

// Per thread of a team, from the set-up of a call.
struct SubstepShareInfo {
  std::uint32_t lower = 0;  // slots with j < i in the share's rows
  bool uniform = true;      // one h and one ρ0 over the share (those of particle 0)
};

struct SubstepWorkspace {
  // Per pair k = (i, j), in the topology's CSR order: the hourglass pair stiffness κ_ij,
  // filled at the start of every call (so a rebuilt topology needs no invalidation).
  std::vector<double> kappa;
  // Per pair, of the current sub-step.
  std::vector<Vec2> keps;  // κ_ij ε_ij (hourglass)
  // Once per pair {i, j}, not per slot (the lower particle's term serves both), at u = k −
  // lower[i] for the slot k of i's row with j > i: the slots with j > i in CSR order. Pass 1
  // streams them, pass 2 reads i's own ones in order and those of its pairs with j < i, at
  // slot reverse[k] of j's row, from the rows of the nearby j.
  std::vector<double> viscous_weight;   // |c_ij| of the artificial viscosity, per call [m]
  std::vector<SubstepViscous> viscous;  // viscous pair terms
  // Per particle.
  std::vector<std::uint32_t> upper;       // first k of i's row with j > i (rows are sorted)
  std::vector<std::uint32_t> lower;       // slots with j < i in the rows 0..i (lower slots)
  std::vector<Vec2> gsum;                 // Σ_j g_ij over i's pairs, per call [1/m]
  std::vector<SubstepParticleMats> mats;  // P and G by columns
  std::vector<Vec2> fext;                 // fluid force + weight, held over the call [N/m]
  std::vector<SubstepPower> power;        // of the sub-step just completed
  std::vector<double> clamp_power;        // of a clamped particle (only those are written)
  std::vector<Vec2> vhalf;                // half-step velocity
  // With an Eulerian switch only (otherwise updated in place): v½ and x after the next kick
  // and drift, swapped with vhalf and body.x after pass 2.
  std::vector<Vec2> vhalf_next;
  std::vector<Vec2> x_next;
  std::vector<double> stress_power;  // P̄ : Ḟ / ρ0 of the sub-step [W/kg]
  std::vector<Mat2> P_kin;           // P Cᵀ after an Eulerian switch (SolidBody::kinematic_P)
  std::vector<SubstepShareInfo> share_info;  // per thread of the team

  void resize(std::size_t particles, std::size_t pairs, std::size_t threads) {
    kappa.resize(pairs);
    keps.resize(pairs);
    // Every pair is stored from both sides (topology.pair_reverse), so pairs / 2 of them.
    viscous_weight.resize(pairs / 2);
    viscous.resize(pairs / 2);
    upper.resize(particles);
    lower.resize(particles);
    stress_power.resize(particles);
    gsum.resize(particles);
    mats.resize(particles);
    fext.resize(particles);
    power.resize(particles);
    clamp_power.resize(particles);
    vhalf.resize(particles);
    share_info.resize(threads);
  }
};

}  // namespace slamsph
