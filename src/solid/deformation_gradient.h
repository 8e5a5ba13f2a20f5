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
Mat2 reference_gradient(const SolidTopology& topo, std::span<const Vec2> f, std::size_t i);

// body.F from body.x.
void compute_deformation_gradients(SolidBody& body, const SolidTopology& topo,
                                   const Executor& exec);

}  // namespace slamsph
