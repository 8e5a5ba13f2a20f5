// Kernel-gradient correction matrix (paper Eq. 11, spec §3):
//   B_i = ( Σ_j V0_j (X_j − X_i) ⊗ ∇0W_ij )⁻¹,
// summed over the pairs of i that belong to i's own gradient set (all kernel neighbours for
// TLSPH, the selected set S_i for TL-SFPM). With it the corrected gradient
// ∇0 f_i = Σ_j V0_j (f_j − f_i) ⊗ B_i ∇0W_ij reproduces linear fields exactly, also where
// the kernel support is cut by a free surface. For a radial kernel the bracket is
// symmetric, so B_i is symmetric and the transpose convention does not matter for B_i
// itself; F_i = Σ_j V0_j (x_j − x_i) ⊗ (B_i ∇0W_ij) then equals F exactly for x = F X + c.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "core/cell_grid.h"
#include "core/vec.h"

namespace slamsph {

class Executor;

// raw_grad[k] = ∇0W_ij for pair k = (i, j) of `pairs`; use[k] = 1 if the pair enters B_i.
// Throws std::invalid_argument if some B_i does not exist (degenerate neighbourhood).
void compute_correction_matrices(std::span<const Vec2> X, std::span<const double> V0,
                                 const NeighbourList& pairs, std::span<const Vec2> raw_grad,
                                 std::span<const std::uint8_t> use, const Executor& exec,
                                 std::vector<Mat2>& B);

}  // namespace slamsph
