#include "solid/deformation_gradient.h"

#include "core/parallel.h"

namespace slamsph {

void compute_deformation_gradients(SolidBody& body, const SolidTopology& topo,
                                   const Executor& exec) {
  body.F.resize(body.size());
  exec.for_each(body.size(),
                [&](std::size_t i) { body.F[i] = reference_gradient(topo, body.x, i); });
}

}  // namespace slamsph
