// Hourglass (zero-energy mode) control for total-Lagrangian particle solids (spec §3 "Known
// risk"). Nearest-neighbour central differences (TL-SFPM) and kernel sums (TLSPH) both
// leave zig-zag displacement fields with F unchanged. Following Ganzenmüller (2015,
// CMAME 286:87, "An hourglass control algorithm for Lagrangian SPH"), the zig-zag part of
// the displacement is measured per pair by the error of the particle's own linear
// prediction,
//   ε_ij = F_i (X_j − X_i) − (x_j − x_i),
// which vanishes for every affine motion (rigid rotation included). Variant used here: the
// control is the exact gradient of the penalty potential
//   E_hg = Σ_i Σ_{j∈pairs(i)} ½ κ_ij |ε_ij|²,   κ_ij = α E V0_i V0_j W(|X_ij|) / |X_ij|²,
// (Ganzenmüller's pair stiffness, α = MaterialConfig::hourglass), so the force
//   f_m = −∂E_hg/∂x_m
// is conservative: E_hg is reported as the hourglass energy and the total energy stays
// conserved; it is invariant under translation and rotation of x, so it conserves linear
// and angular momentum; and it is zero for uniform deformation. With
// G_i = Σ_j κ_ij ε_ij ⊗ X_ij, the gradient gathered for particle m over its pairs j is
//   ∂E_hg/∂x_m = Σ_j [ G_j g_jm − G_m g_mj + κ_mj ε_mj − κ_jm ε_jm ].
// With α = 1 the same E_hg is used as a diagnostic of zig-zag energy whether or not the
// control is on.
#pragma once
#include <span>

#include "solid/solid_body.h"

namespace slamsph {

class Executor;

// κ_ij of pair k = (i, j) with coefficient alpha, with the pair's reference kernel value
// (solid_topology.h: symmetric h_ij, so parts of different spacing get a symmetric
// stiffness): a reference quantity, so the fused sub-step computes it once per pair
// (solid/elastic_substep.h). Forced inline: in the pair loops GCC otherwise keeps a call per
// pair (measured with callgrind: +10 % instructions on the oscillating plate).
[[gnu::always_inline]] inline double hourglass_pair_stiffness(const SolidBody& body,
                                                              const SolidTopology& topo,
                                                              double alpha, std::size_t i,
                                                              std::size_t j, std::uint32_t k) {
  const double r = norm(body.X[j] - body.X[i]);
  return alpha * body.material.youngs_modulus * body.V0[i] * body.V0[j] * topo.w0[k] / (r * r);
}

// First pass for particle i (body.F[i] current, positions x): κ_ij ε_ij of each pair k of i
// into keps[k], and returns G_i = Σ_j κ_ij ε_ij ⊗ X_ij. kappa(k) is κ_ij of pair k.
template <class Stiffness>
inline Mat2 hourglass_moment(const SolidBody& body, const SolidTopology& topo,
                             std::span<const Vec2> x, std::size_t i, Stiffness&& kappa,
                             std::span<Vec2> keps) {
  Mat2 g;
  const Mat2 Fi = body.kinematic_F(i);
  for (std::uint32_t k = topo.pairs.start[i]; k < topo.pairs.start[i + 1]; ++k) {
    const std::uint32_t j = topo.pairs.index[k];
    const Vec2 Xij = body.X[j] - body.X[i];
    keps[k] = kappa(k) * (Fi * Xij - (x[j] - x[i]));
    g += outer(keps[k], Xij);
  }
  return g;
}

// Second pass: the hourglass force −∂E_hg/∂x_m on particle m from every particle's G and
// every pair's κ ε (all of the first pass complete).
inline Vec2 hourglass_force_on(const SolidTopology& topo, std::span<const Mat2> G,
                               std::span<const Vec2> keps, std::size_t m) {
  Vec2 grad;
  for (std::uint32_t k = topo.pairs.start[m]; k < topo.pairs.start[m + 1]; ++k) {
    const std::uint32_t j = topo.pairs.index[k];
    const std::uint32_t rk = topo.pair_reverse[k];
    grad += G[j] * topo.grad0[rk];
    grad -= G[m] * topo.grad0[k];
    grad += keps[k];
    grad -= keps[rk];
  }
  return -grad;
}

// E_hg with coefficient alpha over the pairs of `topo`, from body.x and body.F (F must be
// current) [J/m].
double hourglass_energy(const SolidBody& body, const SolidTopology& topo, double alpha,
                        const Executor& exec);

// f = −∂E_hg/∂x with coefficient alpha (f zero if alpha == 0); needs current body.F.
void compute_hourglass_forces(const SolidBody& body, const SolidTopology& topo, double alpha,
                              const Executor& exec, std::span<Vec2> f);

}  // namespace slamsph
