// Storage of the fused elastic sub-step (solid/elastic_substep.h), kept in the body so that
// the sub-step loop never allocates (vectors are resized once per fluid step, a no-op while
// the sizes stay). The arrays of a large body are on 2 MiB pages (core/huge_pages.h; session
// 20). Not state: derived per call from the topology, the material and the
// body's fields; never persistent, never written out.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/huge_pages.h"
#include "core/vec.h"
#include "solid/substep_levels.h"

namespace slamsph {

// Reference constants of pair k = (i, j) read by pass 1 (F, Ḟ, hourglass moment, viscous
// terms), in one record so that the pass streams one array; j comes from the topology's
// index. 48 bytes: the pair smoothing length and density of the viscous term are formed from
// the per-particle h and ρ0 of i and j (j is near i in the stored order, so in cache), not
// stored per pair.
struct SubstepPairRef {
  Vec2 g;                 // g_ij = topology.grad0[k] [1/m]
  Vec2 X;                 // X_j − X_i [m]
  double kappa;           // hourglass pair stiffness κ_ij [N/m^3·m^2]
  double viscous_weight;  // |c_ij| of the artificial viscosity [m]
};
// Those read by pass 2 (forces).
struct SubstepPairRev {
  Vec2 g_rev;  // g_ji = topology.grad0[pair_reverse[k]] [1/m]
  std::uint32_t j;
  std::uint32_t reverse;
};
// Viscous pair term of the current sub-step: force on i from j (−f of the reverse pair) and
// the heating rate of each particle from the pair [W/m].
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
// summed in particle order later (the forces and velocities they come from are overwritten
// meanwhile) [W/m]: f_av·v, f_hg·v, f_ext·v½ and for a clamped particle
// (f_int + f_ext)·v_clamp.
struct SubstepPower {
  double viscous, hourglass, external, clamp;
};

// The slot-major (ELL) pair layout of the passes' eight lanes (solid/substep_pair_lanes.h):
// slot s of particle i at off[i / 8] + 8 s + i mod 8. Used by the two-pass schedule where
// the CPU has AVX-512F (otherwise empty); per call: off, mask (ell_layout), the pair
// constants (the set-up); per sub-step: keps_* (pass 1, instead of keps), fav and heat (pass
// 1, instead of viscous).
struct SubstepEll {
  HugeVector<std::uint32_t> off;  // per block of eight particles, and the total at the end
  HugeVector<std::uint8_t> mask;  // per block and slot: the lanes with an s-th pair
  HugeVector<double> g_x, g_y, X_x, X_y, kappa, vw;  // pass 1's (SubstepPairRef)
  HugeVector<double> h_pair, rho_pair;               // ½ (h_i + h_j), ½ (ρ0_i + ρ0_j)
  HugeVector<double> g_rev_x, g_rev_y;
  HugeVector<std::int32_t> j, rev_pos;
  HugeVector<double> keps_x, keps_y;
  // Per particle, pass 1 in lanes: the sums of the viscous pair terms for pass 2.
  HugeVector<Vec2> fav;
  HugeVector<double> heat;
  // Per block, the lowest and highest particle its particles pair with (itself included):
  // when its pass 2 may run in the lagged sweep (elastic_substep.cpp).
  HugeVector<std::uint32_t> reach_lo, reach_hi;
};

// The lagged sweep's copies of the body's fields it streams every sub-step (x, F, P, e and the
// constants m, V0, ρ0), on huge pages like the rest (the body's own vectors are on 4 KiB
// pages): copied in at the start of a call, x, F, P and e back at its end.
struct SubstepStage {
  HugeVector<Vec2> x;
  HugeVector<Mat2> F, P;
  HugeVector<double> e, m, V0, rho0;
  void resize(std::size_t n) {
    x.resize(n);
    F.resize(n);
    P.resize(n);
    e.resize(n);
    m.resize(n);
    V0.resize(n);
    rho0.resize(n);
  }
};

struct SubstepWorkspace {
  // Per pair k = (i, j), in the topology's CSR order: reference constants, filled at the
  // start of every call (so a rebuilt topology needs no invalidation), read in the pair
  // loops without the indirections through pair_reverse, X and the per-particle h and ρ0.
  HugeVector<SubstepPairRef> ref;
  HugeVector<SubstepPairRev> rev;
  // Per pair, of the current sub-step.
  HugeVector<Vec2> keps;               // κ_ij ε_ij (hourglass)
  HugeVector<SubstepViscous> viscous;  // viscous pair terms
  // Per particle.
  HugeVector<std::uint32_t> upper;       // first k of i's row with j > i (rows are sorted)
  HugeVector<Vec2> gsum;                 // Σ_j g_ij over i's pairs, per call [1/m]
  HugeVector<SubstepParticleMats> mats;  // V0 P and G by columns
  HugeVector<Vec2> fext;                 // fluid force + weight, held over the call [N/m]
  // One row of n per thread of the team (two-pass schedule: sub-step s in row s mod t, summed
  // by thread r during pass 2 of s + r) or per sub-step of the block (wavefront schedule).
  HugeVector<SubstepPower> power;
  // The sums of each sub-step's powers (two-pass schedule: the chain carried from thread to
  // thread until the last one's share is added).
  HugeVector<SubstepPower> step_sums;
  SubstepLevels levels;    // wavefront: the pair graph's levels
  HugeVector<Vec2> vhalf;  // half-step velocity
  // With an Eulerian switch only (otherwise updated in place): v½ and x after the next kick
  // and drift, swapped with vhalf and body.x after pass 2.
  std::vector<Vec2> vhalf_next;
  std::vector<Vec2> x_next;
  HugeVector<double> stress_power;  // P̄ : Ḟ / ρ0 of the sub-step [W/kg]
  std::vector<Mat2> P_kin;          // P Cᵀ after an Eulerian switch (SolidBody::kinematic_P)
  SubstepEll ell;                   // the pair loops in lanes (two-pass schedule, AVX-512F)
  SubstepStage stage;               // the lagged sweep's copies of body fields

  void resize(std::size_t particles, std::size_t pairs) {
    ref.resize(pairs);
    rev.resize(pairs);
    keps.resize(pairs);
    viscous.resize(pairs);
    upper.resize(particles);
    stress_power.resize(particles);
    gsum.resize(particles);
    mats.resize(particles);
    fext.resize(particles);
    if (power.size() < particles) power.resize(particles);  // the wavefront keeps more
    vhalf.resize(particles);
  }
};

}  // namespace slamsph
