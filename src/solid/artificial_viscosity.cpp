#include "solid/artificial_viscosity.h"

#include <cmath>

#include "core/parallel.h"

namespace slamsph {

double monaghan_pi(Vec2 vij, Vec2 xij, double h, double rho0_mean, double c, double alpha,
                   double beta) {
  const double vx = dot(vij, xij);
  if (vx >= 0.0) return 0.0;
  const double mu = h * vx / (norm2(xij) + 0.01 * h * h);
  return rho0_mean * (-alpha * c * mu + beta * mu * mu);
}

void compute_artificial_viscosity(const SolidBody& body, const SolidTopology& topo,
                                  std::span<const Vec2> v, const Executor& exec, std::span<Vec2> f,
                                  std::span<double> q) {
  const SolidMaterial& mat = body.material;
  const bool off = mat.av_alpha == 0.0 && mat.av_beta == 0.0;
  exec.for_each(body.size(), [&](std::size_t i) {
    Vec2 sum;
    double heat = 0.0;
    if (!off) {
      for (std::uint32_t k = topo.pairs.start[i]; k < topo.pairs.start[i + 1]; ++k) {
        const std::uint32_t j = topo.pairs.index[k];
        const Vec2 xij = body.x[i] - body.x[j];
        const Vec2 vij = v[i] - v[j];
        // Symmetric pair smoothing length (solid_topology.h): body h for one spacing.
        const double h = 0.5 * (topo.h[i] + topo.h[j]);
        const double pi = monaghan_pi(vij, xij, h, 0.5 * (body.rho0[i] + body.rho0[j]),
                                      mat.sound_speed, mat.av_alpha, mat.av_beta);
        if (pi == 0.0) continue;
        const Vec2 c =
            0.5 * (body.V0[i] * topo.grad0[k] - body.V0[j] * topo.grad0[topo.pair_reverse[k]]);
        const double r = norm(xij);
        const double s = pi * norm(c) / r;
        sum += s * xij;
        heat += -0.5 * s * dot(xij, vij);
      }
    }
    f[i] = sum;
    q[i] = heat;
  });
}

}  // namespace slamsph
