// Total-Lagrangian stress force (paper Eq. 10, spec §3):
//   m_i dv_i/dt = V0_i Σ_j V0_j (P_i B_i + P_j B_j) ∇0W_ij
// over the symmetric pair list. With g_ij = V0_j B_i ∇0W_ij (zero where j is not in i's own
// gradient set) and ∇0W_ji = −∇0W_ij this is
//   f_i = Σ_j [ V0_i P_i g_ij − V0_j P_j g_ji ],
// which is the exact gradient −∂/∂x_i of Σ_k V0_k Ψ(F_k) with F_k = Σ_j (x_j − x_k) ⊗ g_kj:
// pair terms are antisymmetric (linear momentum to round-off), and Σ_i x_i × f_i reduces to
// the skew part of Σ_k V0_k F_k P_kᵀ, zero for any law with P Fᵀ symmetric (angular
// momentum to round-off). The stress term P_i B_i ∇0W_ij is therefore dropped for the pairs
// that are only in the union of the TL-SFPM sets (j ∉ S_i): B_i and the gradient of i are
// defined on S_i. Artificial viscosity and hourglass control are separate operators.
#pragma once
#include <span>

#include "solid/solid_body.h"

namespace slamsph {

class Executor;

// Stress force on particle i from body.P over the pairs of `topo` [N/m]. After an Eulerian
// switch's topology rebuild F = F_kin C (SolidBody::F_rebase) and the force takes P Cᵀ,
// the stress conjugate to F_kin: the exact gradient of Σ_k V0_k Ψ(F_kin,k C_k).
inline Vec2 stress_force_on(const SolidBody& body, const SolidTopology& topo, std::size_t i) {
  Vec2 sum;
  const Mat2 Pi = body.V0[i] * body.kinematic_P(i);
  for (std::uint32_t k = topo.pairs.start[i]; k < topo.pairs.start[i + 1]; ++k) {
    const std::uint32_t j = topo.pairs.index[k];
    sum += Pi * topo.grad0[k];
    sum -= body.V0[j] * (body.kinematic_P(j) * topo.grad0[topo.pair_reverse[k]]);
  }
  return sum;
}

// Stress force on every particle from body.P over the pairs of `topo` [N/m].
void compute_stress_forces(const SolidBody& body, const SolidTopology& topo, const Executor& exec,
                           std::span<Vec2> f);

}  // namespace slamsph
