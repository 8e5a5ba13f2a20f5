#include "solid/tl_pair_force.h"

#include "core/parallel.h"

namespace slamsph {

void compute_stress_forces(const SolidBody& body, const SolidTopology& topo, const Executor& exec,
                           std::span<Vec2> f) {
  exec.for_each(body.size(), [&](std::size_t i) { f[i] = stress_force_on(body, topo, i); });
}

}  // namespace slamsph
