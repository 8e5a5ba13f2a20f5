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

// The rotation t = ½ atan2(2 xy, xx − yy) of the principal axes in closed form, without
// trigonometric functions: with d = xx − yy and r = √(d² + 4 xy²), cos 2t = d/r and
// sin 2t = 2 xy / r; the half-angle cosine (d ≥ 0) or sine (d < 0) from √((r ± d)/(2r))
// and the other from sin 2t = 2 c s, so neither suffers cancellation; c ≥ 0 as for the atan2
// form (t in [−π/2, π/2]). A multiple of the identity (r = 0) takes the axes (c, s) = (1, 0).
// Same decomposition as the trigonometric form to round-off, at a small fraction of its cost
// (the Johnson–Cook sub-step, docs/validation.md §6).
inline Spectral spectral(double xx, double xy, double yy) {
  const double d = xx - yy;
  const double r = std::sqrt(d * d + 4.0 * xy * xy);
  double c = 1.0, s = 0.0;
  if (r > 0.0) {
    if (d >= 0.0) {
      c = std::sqrt((r + d) / (2.0 * r));
      s = xy / (r * c);
    } else {
      s = std::copysign(std::sqrt((r - d) / (2.0 * r)), xy);
      c = xy / (r * s);
    }
  }
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
