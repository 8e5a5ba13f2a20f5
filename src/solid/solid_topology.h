// Reference (total-Lagrangian) topology of a solid body (spec §3): which particle pairs
// the solid operators sum over and their precomputed reference gradient weights. It is a
// value of its own, built from X and V0, handed explicitly to every solid operator
// (deformation gradient, stress force, artificial viscosity, hourglass control), and it can
// be rebuilt at any time, for all particles or for a subset.
//
//  - `pairs` is the symmetric pair list the force sum runs over (j in pairs(i) <=> i in
//    pairs(j)); `pair_reverse[k]` is the position of pair (j, i) in j's list.
//  - `grad0[k]` for pair k = (i, j) is the corrected reference gradient weight
//    g_ij = V0_j B_i ∇0W_ij, zero when j is not in i's own gradient set (TL-SFPM: j not in
//    S_i). Every gradient of a field is then ∇0 f_i = Σ_k (f_j − f_i) ⊗ g_ij and
//    F_i = Σ_k (x_j − x_i) ⊗ g_ij (solid/deformation_gradient.h).
//  - TL-SFPM: selected sets S_i (solid/fpm_neighbour_selection.h), their symmetric union as
//    the pair list (solid/symmetric_pairs.h), ∇̂0W_ij the FPM weight gradient
//    (solid/fpm_weight.h), B_i from Eq. 11 over S_i (= M_i⁻¹, solid/correction_matrix.h);
//    g_ij = V0_j B_i ∇̂0W_ij for j ∈ S_i and 0 for the pairs that are only in the union.
//    Then ∇0 f_i = Σ_j (f_j − f_i) ⊗ g_ij is exactly Eqs. 6–8.
//  - TLSPH: every particle in the kernel support (2h), ∇0W_ij = W'(r) (X_i − X_j)/r,
//    B_i from Eq. 11 over the support, g_ij = V0_j B_i ∇0W_ij.
//
// Parts: every particle carries a part id. Pairs join particles of the same part only,
// unless the parts are bonded (`bond_parts`), when pairs may join any two particles of the
// body — the structure a body assembled from several bonded parts needs. Subsets: only
// `active` particles get pairs; the others have empty lists, B = 0 and take no part (e.g.
// to rebuild after particles were removed).
//
// Spacings: a particle may have its own spacing d_i (a fine skin bonded to a coarser
// floor; TL-SFPM only). Particle i selects S_i with d_i (solid/fpm_neighbour_selection.h);
// the gradient stays exact for linear fields on any non-degenerate set, so F is exact for
// every affine motion across the joint. Pair quantities that need a length use the
// symmetric smoothing length h_ij = (h_i + h_j)/2, h_i = h_b d_i/dx: `w0[k]` = W_{h_ij}(|X_ij|)
// (hourglass stiffness) and `h` per particle (artificial viscosity). With one spacing h_i
// is the body's h and w0 its kernel value, bit for bit.
//
// `max_gradient` = max |g_ij|. On a regular lattice of spacing d it is 1/d (a one-sided
// boundary difference, Eq. 7) or less; an irregular joint between parts has larger weights
// (a stiffer pair), which the solid stable step accounts for (solid/body_dynamics.h).
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "core/cell_grid.h"
#include "core/kernel.h"
#include "core/vec.h"
#include "solid/body_kind.h"

namespace slamsph {

class Executor;

struct SolidTopology {
  NeighbourList fpm_sets;                   // TL-SFPM selected sets S_i (empty for TLSPH)
  NeighbourList pairs;                      // symmetric pair list for the force sum
  std::vector<std::uint32_t> pair_reverse;  // index of (j, i) for pair k = (i, j)
  std::vector<Mat2> B;      // correction matrix (Eq. 11; TL-SFPM: the FPM M_i⁻¹) [m^-2 m^2]
  std::vector<Vec2> grad0;  // g_ij = V0_j B_i ∇0W_ij per pair (0 if j not in S_i) [1/m]
  std::vector<std::uint32_t> part;  // part id per particle
  std::vector<double> w0;           // W_{h_ij}(|X_j − X_i|) per pair, symmetric [1/m^2]
  std::vector<double> h;            // smoothing length per particle [m]
  double max_gradient = 0.0;        // max |g_ij| over all pairs [1/m] (solid stable step)

  std::size_t size() const { return pairs.size(); }
};

struct TopologySpec {
  SolidScheme scheme = SolidScheme::TlSfpm;
  double dx = 0.0;                  // particle spacing [m] (TL-SFPM set selection and weight)
  Kernel kernel;                    // TLSPH support and gradient
  std::vector<std::uint32_t> part;  // part id per particle (empty: one part, id 0)
  bool bond_parts = false;          // pairs may join different parts
  std::vector<double> spacing;      // spacing per particle (empty: dx for all) [m]
};

// Builds the topology of the particles `active` (all if empty) of a body with reference
// positions X and volumes V0. Throws std::invalid_argument if some particle has no usable
// gradient set or a singular correction matrix.
SolidTopology build_solid_topology(std::span<const Vec2> X, std::span<const double> V0,
                                   const TopologySpec& spec, const Executor& exec,
                                   std::span<const std::uint32_t> active = {});

}  // namespace slamsph
