// Reference (total-Lagrangian) gradient operators of an elastic body (spec §3), built once
// from X and V0:
//  - TL-SFPM: selected sets S_i (solid/fpm_neighbour_selection.h), their symmetric union as
//    the pair list, ∇̂0W_ij the FPM weight gradient (solid/fpm_weight.h), B_i from Eq. 11
//    over S_i (= M_i⁻¹); g_ij = V0_j B_i ∇̂0W_ij for j ∈ S_i and 0 for the pairs that are
//    only in the union. Then ∇0 f_i = Σ_j (f_j − f_i) ⊗ g_ij is exactly Eqs. 6–8.
//  - TLSPH: every particle in the kernel support (2h), ∇0W_ij = W'(r) (X_i − X_j)/r,
//    B_i from Eq. 11 over the support, g_ij = V0_j B_i ∇0W_ij.
// Fills body.fpm_sets, pairs, pair_reverse, B and grad0.
#pragma once

#include "solid/solid_body.h"

namespace slamsph {

class Executor;

void build_reference_operators(SolidBody& body, const Executor& exec);

}  // namespace slamsph
