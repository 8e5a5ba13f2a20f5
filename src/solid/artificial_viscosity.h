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
inline double monaghan_pi(Vec2 vij, Vec2 xij, double h, double rho0_mean, double c, double alpha,
                          double beta) {
  const double vx = dot(vij, xij);
  if (vx >= 0.0) return 0.0;
  const double mu = h * vx / (norm2(xij) + 0.01 * h * h);
  return rho0_mean * (-alpha * c * mu + beta * mu * mu);
}

// |c_ij| of pair k = (i, j), c_ij = ½(V0_i g_ij − V0_j g_ji): a reference quantity, so the
// fused sub-step computes it once per pair (solid/elastic_substep.h).
inline double viscous_pair_weight(const SolidBody& body, const SolidTopology& topo, std::size_t i,
                                  std::uint32_t k) {
  const std::uint32_t j = topo.pairs.index[k];
  const Vec2 c = 0.5 * (body.V0[i] * topo.grad0[k] - body.V0[j] * topo.grad0[topo.pair_reverse[k]]);
  return norm(c);
}

// Viscous force on particle i [N/m] at positions x and velocities v; adds i's heating rate
// (half of each pair's dissipated power) to `heat` [W/m]. weight(k) is |c_ij| of pair k
// (viscous_pair_weight, possibly precomputed). The caller skips this if α = β = 0.
template <class Weight>
inline Vec2 viscous_force_on(const SolidBody& body, const SolidTopology& topo,
                             std::span<const Vec2> x, std::span<const Vec2> v, std::size_t i,
                             Weight&& weight, double& heat) {
  const SolidMaterial& mat = body.material;
  Vec2 sum;
  for (std::uint32_t k = topo.pairs.start[i]; k < topo.pairs.start[i + 1]; ++k) {
    const std::uint32_t j = topo.pairs.index[k];
    const Vec2 xij = x[i] - x[j];
    const Vec2 vij = v[i] - v[j];
    // Symmetric pair smoothing length (solid_topology.h): body h for one spacing.
    const double h = 0.5 * (topo.h[i] + topo.h[j]);
    const double pi = monaghan_pi(vij, xij, h, 0.5 * (body.rho0[i] + body.rho0[j]), mat.sound_speed,
                                  mat.av_alpha, mat.av_beta);
    if (pi == 0.0) continue;
    const double r = norm(xij);
    const double s = pi * weight(k) / r;
    sum += s * xij;
    heat += -0.5 * s * dot(xij, vij);
  }
  return sum;
}

// Viscous force f (N/m) and heating rate q_i = ½ Σ_j (pair dissipation) [W/m] per particle
// over the pairs of `topo`, from velocities v (spans of body.size()).
void compute_artificial_viscosity(const SolidBody& body, const SolidTopology& topo,
                                  std::span<const Vec2> v, const Executor& exec, std::span<Vec2> f,
                                  std::span<double> q);

}  // namespace slamsph
