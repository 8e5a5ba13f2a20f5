#include "solid/deformation_gradient.h"

#include "core/parallel.h"

namespace slamsph {

void compute_deformation_gradients(SolidBody& body, const SolidTopology& topo,
                                   const Executor& exec) {
  body.F.resize(body.size());
  // After an Eulerian switch F carries the map that keeps it continuous across the
  // topology rebuild (SolidBody::F_rebase).
  const bool rebased = body.eulerian.active;
  exec.for_each(body.size(), [&](std::size_t i) {
    body.F[i] = reference_gradient(topo, body.x, i);
    if (rebased) body.F[i] = body.F[i] * body.F_rebase[i];
  });
}

}  // namespace slamsph
