#include "solid/deformation_gradient.h"

#include "core/parallel.h"

namespace slamsph {

Mat2 reference_gradient(const SolidTopology& topo, std::span<const Vec2> f, std::size_t i) {
  Mat2 G;
  const Vec2 fi = f[i];
  for (std::uint32_t k = topo.pairs.start[i]; k < topo.pairs.start[i + 1]; ++k)
    G += outer(f[topo.pairs.index[k]] - fi, topo.grad0[k]);
  return G;
}

void compute_deformation_gradients(SolidBody& body, const SolidTopology& topo,
                                   const Executor& exec) {
  body.F.resize(body.size());
  exec.for_each(body.size(),
                [&](std::size_t i) { body.F[i] = reference_gradient(topo, body.x, i); });
}

}  // namespace slamsph
