// Deformation gradient and its rate (spec §3, F_i = ∇0 x_i) from the topology's precomputed
// corrected reference gradients g_ij = V0_j B_i ∇0W_ij (solid/solid_topology.h):
//   F_i = Σ_j (x_j − x_i) ⊗ g_ij,   Ḟ_i = Σ_j (v_j − v_i) ⊗ g_ij   (row-major, F_ab = ∂x_a/∂X_b).
// TL-SFPM: exactly the FPM gradient of Eqs. 6–8; TLSPH: the B-corrected kernel gradient.
#pragma once
#include <span>

#include "solid/solid_body.h"

namespace slamsph {

class Executor;

// ∇0 f_i of a vector field f given per particle.
inline Mat2 reference_gradient(const SolidTopology& topo, std::span<const Vec2> f, std::size_t i) {
  Mat2 G;
  const Vec2 fi = f[i];
  for (std::uint32_t k = topo.pairs.start[i]; k < topo.pairs.start[i + 1]; ++k)
    G += outer(f[topo.pairs.index[k]] - fi, topo.grad0[k]);
  return G;
}

// F_i = ∇0 x_i and Ḟ_i = ∇0 v_i in one pass over i's pairs (the same sums, in the same
// order, as two calls of reference_gradient; the fused sub-step, solid/elastic_substep.h).
inline void gradients_of_motion(const SolidTopology& topo, std::span<const Vec2> x,
                                std::span<const Vec2> v, std::size_t i, Mat2& F, Mat2& Fdot) {
  Mat2 G, H;
  const Vec2 xi = x[i], vi = v[i];
  for (std::uint32_t k = topo.pairs.start[i]; k < topo.pairs.start[i + 1]; ++k) {
    const std::uint32_t j = topo.pairs.index[k];
    const Vec2 g = topo.grad0[k];
    G += outer(x[j] - xi, g);
    H += outer(v[j] - vi, g);
  }
  F = G;
  Fdot = H;
}

// body.F from body.x.
void compute_deformation_gradients(SolidBody& body, const SolidTopology& topo,
                                   const Executor& exec);

}  // namespace slamsph
