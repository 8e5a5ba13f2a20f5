// Spectral form of a symmetric in-plane 2×2 tensor, shared by the multiplicative plasticity
// laws (j2_linear_hardening, johnson_cook) for the principal logarithmic strains of b_e.
#pragma once
#include <cmath>

#include "core/vec.h"

namespace slamsph {

// Eigenvalues e1, e2 with unit eigenvectors n1 = (c, s), n2 = (−s, c).
struct Spectral {
  double e1, e2, c, s;
};

// atan2 keeps the decomposition defined for a multiple of the identity.
inline Spectral spectral(double xx, double xy, double yy) {
  const double t = 0.5 * std::atan2(2.0 * xy, xx - yy);
  const double c = std::cos(t), s = std::sin(t);
  return {c * c * xx + 2.0 * c * s * xy + s * s * yy, s * s * xx - 2.0 * c * s * xy + c * c * yy, c,
          s};
}

// Σ_a v_a n_a ⊗ n_a for the in-plane eigenvectors of `sp`.
inline Mat2 compose(const Spectral& sp, double v1, double v2) {
  const double c = sp.c, s = sp.s;
  const double xy = (v1 - v2) * c * s;
  return {v1 * c * c + v2 * s * s, xy, xy, v1 * s * s + v2 * c * c};
}

}  // namespace slamsph
