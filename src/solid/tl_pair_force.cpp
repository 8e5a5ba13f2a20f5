#include "solid/tl_pair_force.h"

#include "core/parallel.h"

namespace slamsph {

void compute_stress_forces(const SolidBody& body, const SolidTopology& topo, const Executor& exec,
                           std::span<Vec2> f) {
  exec.for_each(body.size(), [&](std::size_t i) {
    Vec2 sum;
    const Mat2 Pi = body.V0[i] * body.P[i];
    for (std::uint32_t k = topo.pairs.start[i]; k < topo.pairs.start[i + 1]; ++k) {
      const std::uint32_t j = topo.pairs.index[k];
      sum += Pi * topo.grad0[k];
      sum -= body.V0[j] * (body.P[j] * topo.grad0[topo.pair_reverse[k]]);
    }
    f[i] = sum;
  });
}

}  // namespace slamsph
