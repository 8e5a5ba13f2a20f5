// The fluid side of the fluid–solid contact (add_contact_to_fluid, coupling/contact_rates.cpp)
// in vector lanes, for the Wendland C2 kernel on x86-64 CPUs: eight lanes with AVX-512F
// (coupling/contact_pair_lanes_avx512.cpp, the only file of this domain built with -mavx512f),
// else four with AVX2 (coupling/contact_pair_lanes_avx2.cpp, built with -mavx2); chosen at run
// time, so the binary still runs on any x86-64 (the scalar loop of contact_rates.cpp).
//
// Both run a chunk of fluid particles in three sweeps (coupling/contact_pair_lanes_body.h):
//   1 pack: each listed contact partner that takes part — wetted, faced (a ghost's side) and
//     inside the support, the tests of the scalar loop — appended in list order with dx, r²
//     and the fluid particle's own values;
//   2 physics: contact_pair<kViscous> (coupling/contact_pair.h) on 4 or 8 packed pairs at a
//     time, whatever fluid particle they belong to, every operation the scalar one in the
//     same order (no reassociation, no fused multiply-add: -ffp-contract=off), each pair's
//     total force, viscous force and continuity term stored;
//   3 sums: the scalar loop's additions pair by pair in list order, and the kept pair forces
//     (ContactPairForces) for the reaction.
// So every sum receives the scalar loop's operands in the scalar loop's order: the same bits
// (CouplingContactLanes.*AreBitIdenticalToTheScalarLoop,
// tests/unit/test_coupling_contact_lanes.cpp).
#pragma once
#include <cstdint>

#include "core/vec.h"

namespace slamsph {

// The arrays and constants of one add_contact_to_fluid pass (contact_rates.cpp builds it).
struct ContactLaneData {
  // Fluid.
  const Vec2* xf;
  const Vec2* vf;
  const double* rhof;
  const double* pf;
  const double* mf;
  Vec2* af;       // += force / m (momentum)
  double* drhof;  // += 2 rho sum (continuity)
  // Contact particles.
  const Vec2* xs;
  const Vec2* vs;
  const Vec2* vs_noslip;
  const Vec2* as;
  const double* rhos;
  const double* ps;
  const double* Vs;
  const std::uint8_t* wetted;
  const std::uint8_t* ghost;
  const Vec2* anchor;
  const Vec2* normal;
  // The fluid–contact lists: partners of i are index[start[i] .. start[i + 1]).
  const std::uint32_t* start;
  const std::uint32_t* index;
  // The pair forces kept for the reaction (ContactPairForces), per list entry; null: none.
  Vec2* keep_total;
  Vec2* keep_viscous;
  std::uint8_t* keep_acted;
  double inv_h, w_factor;  // Kernel::inv_h(), Kernel::wendland_dw_over_r_factor()
  double support2;         // Kernel::support() squared
  double eta2;             // 0.01 h h, the Morris regulariser
  double c0, omega, nu, p_min, p_barrier;
  Vec2 gravity;
  bool hydrostatic;  // g_rel = gravity - a_s, else zero (ContactParams::hydrostatic_correction)
  bool viscous;
  bool momentum, continuity;
};

// Packed pairs per chunk; a fluid particle with a longer list goes through the scalar loop
// (the caller, contact_rates.cpp, sends it there).
constexpr std::uint32_t kContactLaneChunk = 128;

// True when this build has the loop and the CPU runs its ISA.
bool contact_lanes_avx2_available();
bool contact_lanes_avx512_available();

// Fluid particles [i_begin, i_end) up to the first with more than kContactLaneChunk listed
// partners: the scalar loop of contact_rates.cpp for the Wendland kernel. Returns that particle
// (i_end if none), for the caller to run through the scalar loop. Only call them when available.
std::uint32_t contact_to_fluid_avx2(const ContactLaneData& d, std::uint32_t i_begin,
                                    std::uint32_t i_end);
std::uint32_t contact_to_fluid_avx512(const ContactLaneData& d, std::uint32_t i_begin,
                                      std::uint32_t i_end);

}  // namespace slamsph
