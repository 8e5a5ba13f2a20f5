// Monaghan artificial viscosity for the solid (spec §3, the Π_ij of paper Eq. 10; Monaghan
// 1992). In stress units (Eq. 10 adds Π_ij to P_i B_i + P_j B_j, as a pressure):
//   μ_ij = h (v_i − v_j)·(x_i − x_j) / (|x_i − x_j|² + 0.01 h²),
//   Π_ij = ρ̄0_ij (−α c μ_ij + β μ_ij²)  if (v_i − v_j)·(x_i − x_j) < 0 (approaching), else 0,
// c the body's P-wave speed. The pair force is applied along the current pair direction
// (central, so it conserves linear and angular momentum to round-off) with the magnitude
// of the symmetric corrected reference gradient |c_ij|, c_ij = ½(V0_i g_ij − V0_j g_ji)
// (= V0_i V0_j ½(B_i + B_j)∇0W_ij where both sets hold the pair):
//   f_i = Σ_j Π_ij |c_ij| (x_i − x_j)/|x_i − x_j|.
// Its power on each pair is −Π_ij |c_ij| |μ-part| ≤ 0: it only dissipates. Half of each
// pair's dissipated power heats each particle (internal energy).
#pragma once
#include <span>

#include "solid/solid_body.h"

namespace slamsph {

class Executor;

// Π_ij [Pa] for relative velocity vij = v_i − v_j and separation xij = x_i − x_j.
double monaghan_pi(Vec2 vij, Vec2 xij, double h, double rho0_mean, double c, double alpha,
                   double beta);

// Viscous force f (N/m) and heating rate q_i = ½ Σ_j (pair dissipation) [W/m] per particle
// over the pairs of `topo`, from velocities v (spans of body.size()).
void compute_artificial_viscosity(const SolidBody& body, const SolidTopology& topo,
                                  std::span<const Vec2> v, const Executor& exec, std::span<Vec2> f,
                                  std::span<double> q);

}  // namespace slamsph
