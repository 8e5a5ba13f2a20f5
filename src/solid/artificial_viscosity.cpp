#include "solid/artificial_viscosity.h"

#include <cmath>

#include "core/parallel.h"

namespace slamsph {

void compute_artificial_viscosity(const SolidBody& body, const SolidTopology& topo,
                                  std::span<const Vec2> v, const Executor& exec, std::span<Vec2> f,
                                  std::span<double> q) {
  const SolidMaterial& mat = body.material;
  const bool off = mat.av_alpha == 0.0 && mat.av_beta == 0.0;
  auto weight = [&](std::size_t i) {
    return [&, i](std::uint32_t k) { return viscous_pair_weight(body, topo, i, k); };
  };
  exec.for_each(body.size(), [&](std::size_t i) {
    double heat = 0.0;
    f[i] = off ? Vec2{} : viscous_force_on(body, topo, body.x, v, i, weight(i), heat);
    q[i] = heat;
  });
}

}  // namespace slamsph
