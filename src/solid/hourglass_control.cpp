#include "solid/hourglass_control.h"

#include <vector>

#include "core/parallel.h"

namespace slamsph {
namespace {

[[gnu::always_inline]] inline Vec2 pair_error(const SolidBody& body, std::size_t i, std::size_t j) {
  return body.kinematic_F(i) * (body.X[j] - body.X[i]) - (body.x[j] - body.x[i]);
}

}  // namespace

double hourglass_energy(const SolidBody& body, const SolidTopology& topo, double alpha,
                        const Executor& exec) {
  if (alpha == 0.0) return 0.0;
  std::vector<double> per(body.size());
  exec.for_each(body.size(), [&](std::size_t i) {
    double s = 0.0;
    for (std::uint32_t k = topo.pairs.start[i]; k < topo.pairs.start[i + 1]; ++k) {
      const std::uint32_t j = topo.pairs.index[k];
      s += 0.5 * hourglass_pair_stiffness(body, topo, alpha, i, j, k) *
           norm2(pair_error(body, i, j));
    }
    per[i] = s;
  });
  double total = 0.0;
  for (double s : per) total += s;
  return total;
}

void compute_hourglass_forces(const SolidBody& body, const SolidTopology& topo, double alpha,
                              const Executor& exec, std::span<Vec2> f) {
  const std::size_t n = body.size();
  if (alpha == 0.0) {
    for (std::size_t i = 0; i < n; ++i) f[i] = Vec2{};
    return;
  }
  // Pass 1: κ ε per pair and G per particle.
  std::vector<Vec2> keps(topo.pairs.index.size());
  std::vector<Mat2> G(n);
  auto kappa = [&](std::size_t i) {
    return [&, i](std::uint32_t k) {
      return hourglass_pair_stiffness(body, topo, alpha, i, topo.pairs.index[k], k);
    };
  };
  exec.for_each(
      n, [&](std::size_t i) { G[i] = hourglass_moment(body, topo, body.x, i, kappa(i), keps); });
  // Pass 2: gather the gradient.
  exec.for_each(n, [&](std::size_t m) { f[m] = hourglass_force_on(topo, G, keps, m); });
}

}  // namespace slamsph
