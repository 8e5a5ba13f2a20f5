#include "solid/deformation_gradient.h"

#include "core/parallel.h"

namespace slamsph {

Mat2 reference_gradient(const SolidBody& body, std::span<const Vec2> f, std::size_t i) {
  Mat2 G;
  const Vec2 fi = f[i];
  for (std::uint32_t k = body.pairs.start[i]; k < body.pairs.start[i + 1]; ++k)
    G += outer(f[body.pairs.index[k]] - fi, body.grad0[k]);
  return G;
}

void compute_deformation_gradients(SolidBody& body, const Executor& exec) {
  body.F.resize(body.size());
  exec.for_each(body.size(),
                [&](std::size_t i) { body.F[i] = reference_gradient(body, body.x, i); });
}

}  // namespace slamsph
