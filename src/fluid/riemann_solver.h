// Linearised (acoustic) Riemann solver with the low-dissipation limiter, spec §2
// (Zhang, Hu & Adams 2017, the paper's ref. [42]; paper Eqs. 1–3 and 5).
//
// The 1D problem lies on the line from particle i (left) to j (right):
//   U* = (rho_L U_L + rho_R U_R + (p_L - p_R)/c0) / (rho_L + rho_R)
//   p* = (rho_R p_L + rho_L p_R)/(rho_L + rho_R) + beta rho_L rho_R (U_L - U_R)/(rho_L + rho_R)
//   beta = min(omega * max(U_L - U_R, 0), c0)
// so separating pairs (U_L < U_R) get no dissipation and approaching ones at most the
// full acoustic impedance. Swapping L and R (and reversing the axis) gives the same p*:
// the pair force is antisymmetric and linear momentum is conserved exactly.
//
// Hydrostatic correction (our addition, docs/model.md §2): the (p_L - p_R)/c0 term of U*
// diffuses pressure. Under gravity the rest state has p_L - p_R = dp_static =
// rho_avg g . (x_i - x_j) != 0 (grad p = rho g), and that diffusion then pumps mass into the
// free-surface layer, which has no neighbour above: still water starts to move (measured: spurious
// speeds ~7 % of sqrt(gH) after 1 s without the correction). As in the hydrostatic
// correction of delta-SPH density diffusion (Antuono et al. 2012), U* uses the
// difference from the static state, (p_L - p_R - dp_static)/c0. p* is unchanged.
#pragma once
#include <algorithm>

namespace slamsph {

struct RiemannState {
  double rho;  // density [kg/m^3]
  double u;    // velocity along the axis from i to j [m/s]
  double p;    // pressure [Pa]
};

struct RiemannStar {
  double u;  // interface velocity U* [m/s]
  double p;  // interface pressure p* [Pa]
};

inline RiemannStar solve_riemann(const RiemannState& L, const RiemannState& R, double c0,
                                 double omega, double dp_static = 0.0) {
  const double inv_sum = 1.0 / (L.rho + R.rho);
  const double du = L.u - R.u;
  const double beta = std::min(omega * std::max(du, 0.0), c0);
  RiemannStar s;
  s.u = (L.rho * L.u + R.rho * R.u + (L.p - R.p - dp_static) / c0) * inv_sum;
  s.p = (R.rho * L.p + L.rho * R.p) * inv_sum + beta * L.rho * R.rho * du * inv_sum;
  return s;
}

}  // namespace slamsph
