// Finite particle method gradient (spec §3, paper Eqs. 6–8): the weighted least-squares
// estimate over a selected set S_i
//   ∇0 f_i = M_i⁻¹ Σ_{j∈S_i} w_ij (f_j − f_i)(X_j − X_i),
//   M_i    = Σ_{j∈S_i} w_ij (X_j − X_i) ⊗ (X_j − X_i).
// Exact for linear fields on any non-degenerate set. The body code evaluates the same
// operator through precomputed pair weights (solid/solid_topology.h); this form is the
// reference used by the tests and for scalar fields.
#pragma once
#include <span>

#include "core/vec.h"

namespace slamsph {

// M_i for neighbour positions Xj with weights w (same length).
Mat2 fpm_moment_matrix(Vec2 Xi, std::span<const Vec2> Xj, std::span<const double> w);

// ∇0 f_i. Throws std::invalid_argument if M_i is singular (collinear set).
Vec2 fpm_gradient(Vec2 Xi, double fi, std::span<const Vec2> Xj, std::span<const double> fj,
                  std::span<const double> w);

}  // namespace slamsph
