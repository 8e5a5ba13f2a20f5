// Weight of the finite particle method (FPM) least-squares gradient (spec §3, paper
// Eqs. 6–8). The paper's corner formula (weights 0.8 / 0.2, Eq. 8) follows when the
// diagonal neighbour weighs 1/3 of an axis neighbour; a power law
//   ŵ(r) = (dx / r)^p,  p = log2 9 ≈ 3.17,  so ŵ(√2 dx) / ŵ(dx) = 1/3 exactly,
// reproduces Eqs. 6–8 exactly on a Cartesian lattice (interior and boundary stencils only
// contain axis neighbours, where any weight gives the same result).
//
// Written as a kernel-like reference gradient ∇̂0W_ij = ŵ(r) (X_j − X_i) / dx⁴ (the dx⁴
// only sets units; every use is multiplied by the correction matrix B_i, Eq. 11, which
// removes the scale). With it, Eq. 11 over the selected set S_i gives B_i = M_i⁻¹ and
// V0_j B_i ∇̂0W_ij = w_ij M_i⁻¹ (X_j − X_i) with w_ij = V0_j ŵ(r_ij) / dx⁴: the FPM gradient
// is the B-corrected gradient over S_i.
#pragma once
#include <cmath>
#include <numbers>

#include "core/vec.h"

namespace slamsph {

inline constexpr double kFpmWeightExponent = 3.1699250014423126;  // log2(9)

inline double fpm_weight(double r, double dx) {
  return std::pow(dx / r, kFpmWeightExponent);
}

// ∇̂0W_ij for the pair (i, j) from reference positions; points from i to j.
inline Vec2 fpm_reference_gradient(Vec2 Xi, Vec2 Xj, double dx) {
  const Vec2 d = Xj - Xi;
  const double dx2 = dx * dx;
  return (fpm_weight(norm(d), dx) / (dx2 * dx2)) * d;
}

}  // namespace slamsph
