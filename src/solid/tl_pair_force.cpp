#include "solid/tl_pair_force.h"

#include "core/parallel.h"

namespace slamsph {

void compute_stress_forces(const SolidBody& body, const Executor& exec, std::span<Vec2> f) {
  exec.for_each(body.size(), [&](std::size_t i) {
    Vec2 sum;
    const Mat2 Pi = body.V0[i] * body.P[i];
    for (std::uint32_t k = body.pairs.start[i]; k < body.pairs.start[i + 1]; ++k) {
      const std::uint32_t j = body.pairs.index[k];
      sum += Pi * body.grad0[k];
      sum -= body.V0[j] * (body.P[j] * body.grad0[body.pair_reverse[k]]);
    }
    f[i] = sum;
  });
}

}  // namespace slamsph
