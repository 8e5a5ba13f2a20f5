// The pair loops of the elastic sub-step's two passes (solid/elastic_substep.cpp) in eight
// AVX-512 lanes, one particle per lane, on x86-64 CPUs that have AVX-512F
// (solid/substep_pair_lanes_avx512.cpp, the only file of this domain built with -mavx512f,
// chosen at run time; elsewhere, in the wavefront schedule and with an Eulerian switch the
// scalar loops run, so the binary still runs on any x86-64). Per particle the law, the
// stress power and pass 2's tail stay scalar, run by the caller after each chunk (since
// session 19 the SVK law, its stress power and V0 P in lanes too: solid/substep_law_lanes.h).
//
// Layout (ELL, slot-major): the particles in blocks of eight consecutive ones; block b holds
// S_b slots (the largest pair count of its particles), slot s of lane l (particle 8b + l)
// at p = off[b] + 8 s + l, so slot s of the eight particles is one contiguous run of eight.
// The per-call pair constants (g_ij, X_ij, κ_ij, |c_ij|, the pair h and ρ0, g_ji, j, the
// position of the reverse pair) are written there by the set-up, κ ε by pass 1, so each pass
// loads its own pairs' records contiguously and reads per lane only what belongs to j: x_j
// and v½_j (pass 1), V0_j P_j and G_j (pass 2; rows of 16 or 64 bytes, transposed into
// components) and κ ε of the reverse pair (pass 2, gathered). Slots beyond a particle's
// pairs are masked out of every sum (the lane keeps its value, as the scalar loop that skips
// them; adding a +0 instead would turn a −0 sum into +0).
//
// Each lane does the scalar loop's operations in its order (fs + (c0 gx + c1 gy), and so on;
// no fused multiply-add: the file is built with -ffp-contract=off), so the sums are those of
// the scalar loops bit for bit (ElasticSubstep.PairLanesBitIdenticalToScalar*). The viscous
// pair terms are the one change of order: the scalar pass 1 computes each pair once, at its
// lower particle, and stores −f for the other; the lanes compute every pair from each side
// and sum them in pass 1 (the same bits, substep_pair_lanes_avx512.cpp says why).
#pragma once
#include <cstddef>
#include <cstdint>

namespace slamsph {

// Particles per call of the lanes: the caller runs pass 2's tail over the same particles
// after each call, while their records are in the cache.
constexpr std::size_t kSubstepLaneChunk = 64;

// The ELL arrays and pass 2's inputs (pointers into SubstepWorkspace::ell and ::mats).
struct SubstepLaneData {
  const std::uint32_t* off;  // per block of eight particles: position of its slot 0
  const std::uint8_t* mask;  // per block and slot (at off[b] / 8 + s): lanes with a pair
  const double* g_rev_x;     // g_ji by components [1/m]
  const double* g_rev_y;
  const std::int32_t* j;        // the partner (a masked slot: the lane's own particle)
  const std::int32_t* rev_pos;  // the reverse pair's position (a masked slot: its own)
  const double* keps_x;         // κ_ij ε_ij of the current sub-step
  const double* keps_y;
  const double* mats;  // SubstepParticleMats per particle: 8 doubles (vp_c0, vp_c1, g_c0, g_c1)
  bool hourglass;
};

// Sums of i's pair terms for the particles of one chunk, by component, i at i − base.
struct SubstepLaneSums {
  alignas(64) double fs_x[kSubstepLaneChunk], fs_y[kSubstepLaneChunk];
  alignas(64) double grad_x[kSubstepLaneChunk], grad_y[kSubstepLaneChunk];
};

// Pass 1's pair loops in the same lanes: F and Ḟ (Σ (x_j − x_i) ⊗ g_ij, Σ (v½_j − v½_i) ⊗
// g_ij), the sums of the viscous pair terms (every pair from i's side, so nothing is written
// to j's slots: the sums pass 2 would form, bit for bit; substep_pair_lanes_avx512.cpp),
// then κ ε per pair and the hourglass moment G = Σ κ ε ⊗ X_ij. The law, the stress power and
// V0 P follow per particle in the caller after each call (SVK: substep_law_lanes.h).
struct SubstepLane1Data {
  const std::uint32_t* off;
  const std::uint8_t* mask;
  const double* g_x;  // g_ij by components [1/m]
  const double* g_y;
  const double* X_x;  // X_j − X_i [m]
  const double* X_y;
  const double* kappa;     // κ_ij
  const double* vw;        // |c_ij| of the viscous term [m]
  const double* h_pair;    // ½ (h_i + h_j) [m]
  const double* rho_pair;  // ½ (ρ0_i + ρ0_j) [kg/m^3]
  const std::int32_t* j;
  const std::int32_t* rev_pos;
  const double* x;   // positions, (x, y) per particle
  const double* vh;  // half-step velocities, likewise
  double c, av_alpha, av_beta;
  double* keps_x;  // out: κ ε per pair
  double* keps_y;
  bool hourglass, viscous;
};

// Pass 1's sums of a chunk by component, i at i − base: F, Ḟ and G (xx, xy, yx, yy), the
// viscous force and heat.
struct SubstepLane1Sums {
  alignas(64) double F[4][kSubstepLaneChunk];
  alignas(64) double fav_x[kSubstepLaneChunk], fav_y[kSubstepLaneChunk];
  alignas(64) double heat[kSubstepLaneChunk];
  alignas(64) double Fd[4][kSubstepLaneChunk];
  alignas(64) double G[4][kSubstepLaneChunk];
};

// True when this build has the lanes and the CPU runs AVX-512F.
bool substep_lanes_avx512_available();

// Pass 1's pair loops of particles [i0, i1) ⊂ [base, base + kSubstepLaneChunk), base a
// multiple of 8 (see SubstepLane1Data). Only call it when substep_lanes_avx512_available().
void substep_lanes_avx512_pass1(const SubstepLane1Data& d, std::size_t base, std::size_t i0,
                                std::size_t i1, SubstepLane1Sums& out);

// Pass 2's pair sums of particles [i0, i1) ⊂ [base, base + kSubstepLaneChunk), base a
// multiple of 8: fs = Σ V0_j P_j g_ji and grad = Σ (G_j g_ji + κ ε_ij − κ ε_ji) (hourglass),
// each from 0 in the pairs' order. Only call it when substep_lanes_avx512_available().
void substep_lanes_avx512_pass2(const SubstepLaneData& d, std::size_t base, std::size_t i0,
                                std::size_t i1, SubstepLaneSums& out);

}  // namespace slamsph
