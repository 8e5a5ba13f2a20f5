// The St Venant–Kirchhoff law of the elastic sub-step's pass 1 in eight AVX-512 lanes, one
// particle per lane (solid/substep_law_lanes_avx512.cpp, built with -mavx512f
// -ffp-contract=off, chosen at run time with the pair loops: substep_lanes_avx512_available,
// solid/substep_pair_lanes.h). It follows pass 1's pair loops in lanes, whose F and Ḟ are
// already by component per chunk (SubstepLane1Sums), and does per lane what pass 1's scalar
// tail does for SVK (solid/elastic_substep.cpp pass1_law; solid/materials/
// st_venant_kirchhoff.h svk_pk1): E = ½(FᵀF − I), S = 2μ E + λ tr E I, P = F S, the stress
// power ½(P_old + P):Ḟ / ρ0 and V0 P, each the scalar code's operations in its order (no
// fused multiply-add), so the same bits (ElasticSubstep.PairLanesBitIdenticalToScalar*).
// Other laws, an Eulerian switch and the wavefront keep the scalar law.
#pragma once
#include <cstddef>

#include "solid/substep_pair_lanes.h"

namespace slamsph {

// Inputs and outputs of the law's lanes (pointers into SolidBody and SubstepWorkspace).
struct SubstepSvkLaneData {
  double lambda, mu;     // Lamé parameters [Pa]
  const double* V0;      // reference volume per particle [m^2]
  const double* rho0;    // reference density per particle [kg/m^3]
  double* F;             // out: Mat2 per particle (xx, xy, yx, yy)
  double* P;             // in: P of the last sub-step; out: P at F
  double* stress_power;  // out: ½(P_old + P):Ḟ / ρ0 per particle [W/kg]
  double* mats;          // SubstepParticleMats (8 doubles); out: V0 P by columns (the first 4)
};

// The law of particles [i0, i1) ⊂ [base, base + kSubstepLaneChunk), base a multiple of 8,
// from the chunk's F and Ḟ (in `s`, i at i − base). Only call it when
// substep_lanes_avx512_available().
void substep_lanes_avx512_svk(const SubstepSvkLaneData& d, std::size_t base, std::size_t i0,
                              std::size_t i1, const SubstepLane1Sums& s);

}  // namespace slamsph
